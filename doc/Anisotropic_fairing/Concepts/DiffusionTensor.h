/*!
\ingroup PkgAnisotropicFairingConcepts
\cgalConcept
\headerfile DiffusionTensor.h <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

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

A model may also have `double prefilter_time() const`: when it returns \f$\varepsilon > 0\f$, before every
assembly the surface after one isotropic implicit step of length \f$\varepsilon\f$ (model units) from the
current one, \f$M_\varepsilon\f$, is computed, and its derivatives at the same quadrature points are passed
in `Quadrature_point_geometry::prefiltered_t1` etc. (Bajaj and Xu's prefiltered curvature).

A model may also have `bool normal_motion_only() const`: when it returns `true`, each step's displacement
of a control point loses its component in the limit tangent plane at that vertex (in the coupled mode, in
\f$\mathbb{R}^{3+d}\f$; of \f$M_\varepsilon\f$ when `prefilter_time()` > 0; with the linear element, the plane
of Loop's closed-form tangent masks applied to the mesh's vertices), so that the surface moves along
its normal only; the report's
`Fairing_report::normal_motion_only` says so. A tensor that varies along the surface moves points
tangentially too, which only reparametrises the surface in the continuum but can fold it on noisy meshes
(see `CGAL::Anisotropic_fairing::Anisotropic_diffusion_tensor`).

\cgalHasModel `CGAL::Anisotropic_fairing::Isotropic_diffusion_tensor`
\cgalHasModel `CGAL::Anisotropic_fairing::Uniform_diffusion_tensor`
\cgalHasModel `CGAL::Anisotropic_fairing::Anisotropic_diffusion_tensor`
*/
class DiffusionTensor
{
public:
  /// returns \f$A\f$ at the quadrature point described by `q` (the current surface's tangents,
  /// second derivatives, metric, and the face's basis functions to interpolate per-vertex data)
  CGAL::Anisotropic_fairing::Parametric_tensor operator()(const CGAL::Anisotropic_fairing::Quadrature_point_geometry& q) const;

  /// \name Optional members
  /// Each is found at compile time (in one place, `internal/flow/Tensor_hooks.h`); a model without it
  /// behaves as the default said here.
  /// @{

  /// (optional) receives the model's scale \f$\ell\f$ before the first assembly (see above); without it,
  /// parameters are in model units
  void set_length_scale(double l);

  /// (optional) the prefilter time \f$\varepsilon\f$ in model units (see above); default 0: no prefilter
  double prefilter_time() const;

  /// (optional) whether each step keeps only the normal component of the motion (see above); default `false`
  bool normal_motion_only() const;

  /// (optional) the feature threshold in model units (1/length), reported as
  /// `Fairing_report::feature_threshold`; default 0
  double threshold() const;

  /// (optional) whether the package chooses the model's parameters from the mesh when it chooses the time
  /// step (automatic parameters); it then calls `choose()`, and compares the result with the isotropic
  /// flow's (see `anisotropic_fairing()`); default `false`
  bool is_automatic() const;

  /// (optional, with `is_automatic()`) sets the threshold in units of \f$1/h\f$ and the prefilter time in
  /// units of \f$h^2\f$, \f$h\f$ the mean edge length of each connected component
  void choose(double lambda, double epsilon);
  /// @}
};
