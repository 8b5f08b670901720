/*!
\ingroup PkgAnisotropicFairingConcepts
\cgalConcept

The diffusion tensor \f$D\f$ of the fairing equation \f$\partial_t x = \mathrm{div}_M(D\nabla_M x)\f$,
given to `CGAL::Anisotropic_fairing::anisotropic_fairing()` by the named parameter `diffusion_tensor`.

The stiffness matrix is \f$L_{ij} = \int (D\nabla\phi_i)\cdot\nabla\phi_j\,dA\f$. At each quadrature
point the gradients of the basis functions are \f$\nabla\phi = T G^{-1}\partial\phi\f$ with
\f$T = [t_1\ t_2]\f$ the tangents and \f$G = T^T T\f$ the metric, so a tangential tensor \f$D\f$
enters only through the symmetric \f$2\times 2\f$ matrix \f$A = G^{-1}T^T D T G^{-1}\f$ in the face's
parameters: \f$(D\nabla\phi_i)\cdot\nabla\phi_j = \partial\phi_i^T A\,\partial\phi_j\f$. A model
returns \f$A\f$, which must be positive semi-definite (for \f$D = I\f$, \f$A = G^{-1}\f$).

The object is copied into the named-parameter pack; pass `std::cref(t)` for a heavy one. With TBB,
`operator()` is called concurrently from several threads, so it must not modify shared state.

A model may also have `void set_length_scale(double l)`: `anisotropic_fairing()` then calls it on its copy,
before the first assembly, with the model's scale \f$\ell = \sqrt{\mathrm{Area}/4\pi}\f$ (of the input's
surface, in \f$\mathbb{R}^{3+d}\f$ in the coupled mode), so that parameters can be given relative to it.

\cgalHasModel `CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor`
\cgalHasModel `CGAL::Anisotropic_fairing::Anisotropic_diffusion_tensor`
*/
class DiffusionTensor
{
public:
  /// returns \f$A\f$ at the quadrature point described by `q` (the current surface's tangents,
  /// second derivatives, metric, and the face's basis functions to interpolate per-vertex data)
  CGAL::Anisotropic_fairing::Parametric_tensor operator()(const CGAL::Anisotropic_fairing::Quadrature_point_geometry& q) const;
};
