// The Python module's arrays in and out: numpy arrays checked as the program checks a file (the message
// names the array and its row), the mesh they make, and the arrays of a mesh's points and vectors.
#ifndef AF_PYTHON_MESH_ARRAYS_H
#define AF_PYTHON_MESH_ARRAYS_H

#include "tool_common.h"
#include "vertex_split.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <string>
#include <vector>

namespace af_python {

namespace py = pybind11;
using af_tool::Mesh;

/// "(3, 4) and dtype int64": what an array is, for messages.
std::string describe(const py::array& a);

/// `a` as a C-contiguous float64 array of `rows` x `cols` (rows < 0: any; cols < 0: any, and a 1-D array is
/// one column); integers (and with `booleans`, booleans) are converted, anything else is refused with a
/// message that names `name`.
py::array_t<double, py::array::c_style> real_matrix(py::handle a, const std::string& name, py::ssize_t rows,
                                                    py::ssize_t cols, bool booleans = false);

/// The mesh of V (N x 3 float64) and F (M x 3 integers), checked as the program checks a file: every index,
/// every coordinate, and that the faces form an oriented 2-manifold (the message names the row of F). With
/// `split`, faces that do not are made one as the program makes them (vertex_split.h: the copies of split
/// vertices after V's), with a warning and the lines of `changes` saying what was done; without, refused.
Mesh mesh_from_arrays(py::handle V, py::handle F, af_tool::Vertex_split* split = nullptr,
                      std::vector<std::string>* changes = nullptr);

/// The first `count` points of the mesh (all of them by default), N x 3.
py::array_t<double> points_array(const Mesh& mesh, std::size_t count = std::size_t(-1));

/// N x 3 of anything indexed [i][c].
template <typename Vectors>
py::array_t<double> vectors_array(const Vectors& values)
{
  py::array_t<double> out({ py::ssize_t(values.size()), py::ssize_t(3) });
  auto o = out.mutable_unchecked<2>();
  for(std::size_t i = 0; i < values.size(); ++i)
    for(int c = 0; c < 3; ++c) o(py::ssize_t(i), c) = values[i][c];
  return out;
}

} // namespace af_python

#endif // AF_PYTHON_MESH_ARRAYS_H
