// The Python module's arrays in and out (mesh_arrays.h).
#include "mesh_arrays.h"

#include "mesh_file_check.h"
#include "mesh_repair.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace af_python {

using namespace af_tool;

std::string describe(const py::array& a)
{
  std::string shape = "(";
  for(py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
  return shape + (a.ndim() == 1 ? ",)" : ")") + " and dtype " + py::str(a.dtype()).cast<std::string>();
}

py::array_t<double, py::array::c_style> real_matrix(py::handle a, const std::string& name, py::ssize_t rows,
                                                    py::ssize_t cols, bool booleans)
{
  py::array arr = py::array::ensure(a);
  if(!arr) throw py::type_error(name + " must be a numpy array (or a nested list) of real numbers");
  const char kind = arr.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u' && !(booleans && kind == 'b'))
    throw py::type_error(name + (booleans ? " must hold booleans or numbers" : " must hold real numbers (float64)") +
                         ", not an array of " + describe(arr));
  const bool column = cols < 0 && arr.ndim() == 1;
  if(!(arr.ndim() == 2 || column) || (cols > 0 && arr.shape(1) != cols))
    throw py::value_error(name + " must be an " +
                          (cols > 0 ? "N x " + std::to_string(cols) : std::string("N x d (or N)")) +
                          " array, not one of " + describe(arr));
  if(rows >= 0 && arr.shape(0) != rows)
    throw py::value_error(name + " must have one row per vertex (" + std::to_string(rows) + "), not an array of " +
                          describe(arr));
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arr);
}

Mesh mesh_from_arrays(py::handle V, py::handle F, Vertex_split* split, std::vector<std::string>* changes)
{
  const auto points = real_matrix(V, "V", -1, 3);
  py::array faces_in = py::array::ensure(F);
  if(!faces_in) throw py::type_error("F must be a numpy array (or a nested list) of vertex indices");
  const char kind = faces_in.dtype().kind();
  if(kind != 'i' && kind != 'u')
    throw py::type_error("F must hold integer vertex indices, not an array of " + describe(faces_in));
  if(faces_in.ndim() != 2 || faces_in.shape(1) != 3)
    throw py::value_error("F must be an M x 3 array of triangles, not one of " + describe(faces_in));
  const auto faces = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(faces_in);
  const py::ssize_t n = points.shape(0), m = faces.shape(0);
  if(m == 0) throw py::value_error("F has no face: nothing to fair");

  Polygon_soup soup;
  soup.path = "F";
  auto p = points.unchecked<2>();
  for(py::ssize_t i = 0; i < n; ++i)
  {
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(p(i, c))) throw py::value_error("V row " + std::to_string(i) + " is not finite");
    soup.points.push_back({ p(i, 0), p(i, 1), p(i, 2) });
  }
  auto f = faces.unchecked<2>();
  for(py::ssize_t k = 0; k < m; ++k)
  {
    std::vector<std::size_t> face;
    for(int c = 0; c < 3; ++c)
    {
      if(f(k, c) < 0 || f(k, c) >= n)
        throw py::value_error("F row " + std::to_string(k) + " refers to vertex " + std::to_string(f(k, c)) +
                              ", but V has " + std::to_string(n) + " vertices (0.." + std::to_string(n - 1) + ")");
      face.push_back(std::size_t(f(k, c)));
    }
    soup.faces.push_back(face);
    soup.face_place.push_back("row " + std::to_string(k));
  }
  try
  {
    check_oriented_manifold(soup);
  }
  catch(const File_problem& e)
  {
    if(!split) throw py::value_error(e.what());
    const Soup_repair fixed = repair_soup(soup);
    try { check_oriented_manifold(soup); }
    catch(const File_problem& again) { throw py::value_error(again.what()); }
    split->file_vertices = std::size_t(n);
    split->copy_of = fixed.copy_of;
    split->split_vertices = fixed.split_vertices;
    std::string said;
    for(const std::string& c : fixed.changes) said += (said.empty() ? "" : "; ") + c;
    *changes = fixed.changes;
    const std::string warning =
      std::string(e.what()) + ": for the run, " + said +
      (fixed.copy_of.empty() ? "" : "; each split vertex is returned once, at the mean of its copies");
    if(PyErr_WarnEx(PyExc_UserWarning, warning.c_str(), 2) != 0) throw py::error_already_set();
  }
  Mesh mesh;
  for(const auto& q : soup.points) mesh.add_vertex(Point(q[0], q[1], q[2]));
  for(const auto& face : soup.faces)
    if(mesh.add_face(Vertex_index(Mesh::size_type(face[0])), Vertex_index(Mesh::size_type(face[1])),
                     Vertex_index(Mesh::size_type(face[2]))) == Mesh::null_face())
      throw py::value_error("F: the triangles cannot form a 2-manifold mesh");
  return mesh;
}

py::array_t<double> points_array(const Mesh& mesh, std::size_t count)
{
  count = std::min(count, std::size_t(mesh.number_of_vertices()));
  py::array_t<double> out({ py::ssize_t(count), py::ssize_t(3) });
  auto o = out.mutable_unchecked<2>();
  for(std::size_t v = 0; v < count; ++v)
    for(int c = 0; c < 3; ++c) o(py::ssize_t(v), c) = mesh.point(Vertex_index(Mesh::size_type(v)))[c];
  return out;
}

} // namespace af_python
