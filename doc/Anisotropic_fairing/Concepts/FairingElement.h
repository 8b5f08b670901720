/*!
\ingroup PkgAnisotropicFairingConcepts
\cgalConcept
\headerfile FairingElement.h <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

The finite element the time stepping runs on: for each face of the mesh, the basis functions that are
non-zero on it and their values and derivatives at the face's quadrature points. This concept is for
those who extend the package. Users choose an element with the named parameter `finite_element`; the
models are internal classes.

The assembly of \f$M\f$ and \f$L(D)\f$, the sparsity pattern and the time stepper only ask the questions
below. They do not know whether they run on Loop patches or on linear hat functions, so a new element is
added by writing a model. Faces whose stencils are equal (for Loop, faces whose rings have the same
valences in the same places) share a *category*, and each category stores its stencils once.

Stencil rows are numbered in the order value, \f$\partial_1\f$, \f$\partial_2\f$, \f$\partial_{11}\f$,
\f$\partial_{12}\f$, \f$\partial_{22}\f$ (0 to 5; derivatives with respect to the face's parameters
\f$(\xi_1, \xi_2)\f$ on the unit triangle). The parameter triangle has area 1/2, which the assembly
multiplies in.

\cgalHasModel `CGAL::Anisotropic_fairing::internal::Patch_cache` (Loop patches of a closed mesh)
\cgalHasModel `CGAL::Anisotropic_fairing::internal::Ghosted_patch_cache` (Loop patches with the ghost layer of a mesh with borders, the ghosts' rows folded onto the real vertices)
\cgalHasModel `CGAL::Anisotropic_fairing::internal::Linear_element_cache` (linear hat functions on the mesh itself)
*/
class FairingElement
{
public:
  /// whether stencil rows 3 to 5 (the second derivatives) are filled. When they are not (the linear
  /// element), the curvature integral is computed from the discrete Laplacian instead.
  static constexpr bool has_second_derivatives;

  /// the faces integrated over (the real faces of the mesh)
  std::size_t number_of_faces() const;

  /// the category of face `f`
  int category(std::size_t f) const;

  /// the number of control vertices whose basis functions are non-zero on face `f`
  int ring_size(std::size_t f) const;

  /// those vertices, in the order of the stencil's columns
  const int* ring(std::size_t f) const;

  /// for stencil row `r` of category `c`: one row per quadrature point, one column per ring vertex, holding
  /// the basis functions' value (r = 0) or derivative there. The matrix type is a row-major
  /// `Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>`.
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& quadrature_rows(int c, int r) const;

  /// the weights of the quadrature points of category `c`, summing to 1
  const Eigen::VectorXd& quadrature_weights(int c) const;
};
