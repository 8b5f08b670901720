// Results whose error to the unit sphere is known exactly, for the tests of the risk estimates.
#ifndef AF_TEST_SUPPORT_UNIT_SPHERE_H
#define AF_TEST_SUPPORT_UNIT_SPHERE_H

namespace AF_test {

/// The rows of Y (points) moved a fraction `w` of the way onto the unit sphere along their radii.
template <typename Matrix>
Matrix toward_sphere(const Matrix& Y, double w)
{
  Matrix Z = Y;
  for(Eigen::Index i = 0; i < Y.rows(); ++i) Z.row(i) = Y.row(i) + w * (Y.row(i) / Y.row(i).norm() - Y.row(i));
  return Z;
}

} // namespace AF_test

#endif // AF_TEST_SUPPORT_UNIT_SPHERE_H
