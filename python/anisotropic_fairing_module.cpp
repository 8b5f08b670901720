// anisotropic_fairing._core, the compiled part of the Python package anisotropic_fairing (pybind11): the
// package's fairing and limit surface on numpy arrays. The package (src/anisotropic_fairing/__init__.py)
// gives fair() its typed keyword parameters and its documentation. fair() reads its keyword arguments
// straight into the command-line program's options and makes the program's library call (fairing_call.h),
// so that its defaults, its checks, its result and its report (the program's JSON, as a dict) are the
// program's.
#include "fairing_call.h"
#include "json_report.h"
#include "keyword_arguments.h"
#include "mesh_arrays.h"
#include "mesh_file_check.h"
#include "mesh_repair.h"
#include "option_words.h"
#include "options.h"
#include "vertex_split.h"

#include <CGAL/Anisotropic_fairing/Input_error.h>
#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Real_timer.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <exception>
#include <stdexcept>
#include <memory>
#include <string>
#include <vector>

namespace py = pybind11;
using namespace af_tool;
using namespace af_python;

namespace {

struct Fairing_failed : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Thrown by the step callback to end the library's call at once (no further step, no further run of the
// default run's comparison) when a Python exception is to be raised: Ctrl-C, or one the callback raised.
struct Run_abandoned
{
};

// ---- fair() ----------------------------------------------------------------------------------------

// The keyword arguments of fair(): the rows of the parameter table that have one (the library's named
// parameters and the anisotropic tensor's settings), read straight into the program's Options (its
// Fairing_options and the words its report names); the library checks the values' ranges and names the
// parameter when it refuses one.
struct Keyword
{
  const char* name;
  void (*take)(Options& o, const std::string& name, py::handle value);
  std::vector<const char*> words;   // the words it takes (none: a number)
};

template <typename Kind> bool has_keyword(const Kind& kind) { return kind.keyword; }
template <typename Kind> std::vector<const char*> words_of_kind(const Kind& kind) { return kind.words(); }

// A spelling kept working: the keyword it reads as, the warning it gives, and the keyword it is listed after.
struct Deprecated_keyword
{
  const char* name;
  const char* now;
  const char* warning;
  const char* after;
};
const Deprecated_keyword deprecated_keywords[] = {
  {"maximum_deviation", "relative_maximum_deviation",
   "maximum_deviation is relative (units of l); write relative_maximum_deviation, or absolute_maximum_deviation "
   "for model units",
   "absolute_maximum_deviation"},
};

// fair()'s keywords in the table's order, each deprecated spelling after the keyword it is listed after
const std::vector<Keyword>& keywords()
{
  static const std::vector<Keyword> table = [] {
    std::vector<Keyword> all, listed;
#define AF_PARAMETER(name, type, default_value, named, setting, check, flag, value, program, python, help) \
  if(has_keyword(python))                                                                                   \
    all.push_back({#name,                                                                                   \
                   [](Options& o, const std::string& k, py::handle v) {                                     \
                     const auto take = python;                                                              \
                     take(o, o.fairing.name, k, v);                                                         \
                   },                                                                                       \
                   words_of_kind(python)});
#define AF_TENSOR_SETTING(name, flag, value, program, python, help) \
  all.push_back({#name,                                             \
                 [](Options& o, const std::string& k, py::handle v) { \
                   const auto take = python;                        \
                   take(o, k, v);                                   \
                 },                                                 \
                 words_of_kind(python)});
#include <CGAL/Anisotropic_fairing/internal/parameter_table.h>
#undef AF_PARAMETER
#undef AF_TENSOR_SETTING
    for(const Keyword& k : all)
    {
      listed.push_back(k);
      for(const Deprecated_keyword& d : deprecated_keywords)
        if(std::string(k.name) == d.after)
          for(const Keyword& now : all)
            if(std::string(now.name) == d.now) listed.push_back({d.name, now.take, now.words});
    }
    return listed;
  }();
  return table;
}

const Keyword& keyword_named(const std::string& name)
{
  for(const Keyword& k : keywords())
    if(name == k.name) return k;
  std::string list;
  for(const Keyword& k : keywords()) list += std::string(", ") + k.name;
  throw py::type_error("fair() got an unexpected keyword argument '" + name +
                       "' (it takes: attributes, vertex_is_constrained, callback, quiet" + list + ")");
}

// One keyword argument into `o`: a deprecated spelling warns, and gives the relative bound once at most.
void take_keyword(Options& o, const std::string& name, py::handle value, bool& relative_bound)
{
  const Keyword& k = keyword_named(name);
  if(value.is_none()) return;   // None: the default
  for(const Deprecated_keyword& d : deprecated_keywords)
    if(name == d.name && PyErr_WarnEx(PyExc_DeprecationWarning, d.warning, 2) != 0) throw py::error_already_set();
  if((name == "maximum_deviation" || name == "relative_maximum_deviation") && std::exchange(relative_bound, true))
    throw py::value_error("give one of relative_maximum_deviation and absolute_maximum_deviation "
                          "(maximum_deviation: the relative one's deprecated spelling), not more");
  k.take(o, name, value);
}

// The checks between the keywords, then the tensor they make (as the program's parse_arguments does).
void check_keywords(Options& o, py::ssize_t attribute_columns)
{
  const bool asked_anisotropic = o.tensor == "anisotropic";   // the tensor's settings need it said
  for(const auto& setting : {std::make_pair(o.has_lambda, "lambda_"), std::make_pair(o.has_epsilon, "epsilon"),
                             std::make_pair(o.has_tangential_motion, "tangential_motion")})
    if(setting.first && !asked_anisotropic)
      throw py::value_error(std::string(setting.second) + " needs tensor anisotropic");
  const AF::Attribute_mode mode = effective_mode(o);
  if(attribute_columns == 0 && (mode == AF::Attribute_mode::COUPLED || mode == AF::Attribute_mode::ATTRIBUTES_ONLY))
    throw py::value_error(std::string("attribute_mode ") + mode_name(mode) + " needs attributes");
  const bool settings = o.has_lambda || o.has_epsilon || o.has_tangential_motion;
  o.fairing.diffusion_tensor = package_tensor(o.tensor, o.fairing.automatic_parameters(), settings, o.lambda, o.epsilon,
                                              o.normal_motion_only);
}

// The program's options for these keyword arguments (`attribute_columns`: of the attributes given).
Options options_of(const py::kwargs& kwargs, py::ssize_t attribute_columns)
{
  Options o;
  o.quiet = true;
  for(py::ssize_t c = 0; c < attribute_columns; ++c) o.attributes.push_back(std::to_string(c));
  bool relative_bound = false;
  for(const auto& item : kwargs) take_keyword(o, py::str(item.first).cast<std::string>(), item.second, relative_bound);
  check_keywords(o, attribute_columns);
  return o;
}

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// The vertex normals of the faired surface as the program writes them for an input with normals: the exact
// normals of the Loop limit surface of the faired control points where the limit surface is written,
// else (control points, linear element) CGAL's compute_vertex_normals of the mesh written; None when the
// geometry was not faired (attribute_mode 'attributes': the input's normals are still right).
py::object written_normals(const Mesh& written, const std::vector<Point>& control_points, const Options& o,
                           AF::Attribute_mode mode, const Vertex_split& split)
{
  if(mode == AF::Attribute_mode::ATTRIBUTES_ONLY) return py::none();
  std::vector<Vector> normals(written.number_of_vertices(), Vector(0, 0, 0));
  if(o.fairing.finite_element == AF::Finite_element::LOOP &&
     o.fairing.output_positions == AF::Output_positions::LIMIT_SURFACE)
  {
    Mesh control = written;
    for(Vertex_index v : control.vertices()) control.point(v) = control_points[std::size_t(v)];
    const AF::Loop_limit_surface<Mesh> limit(control, AF::parameters::quadrature_degree(4));
    limit.limit_normals(CGAL::make_property_map(normals));
  }
  else
  {
    auto map = CGAL::make_property_map(normals);
    CGAL::Polygon_mesh_processing::compute_vertex_normals(written, map);
  }
  // a split vertex: the mean of its copies' normals, normalised
  std::vector<std::vector<double>> columns(normals.size());
  for(std::size_t v = 0; v < normals.size(); ++v) columns[v] = { normals[v].x(), normals[v].y(), normals[v].z() };
  merge_copies(columns, split);
  normals.resize(split.empty() ? normals.size() : split.file_vertices);
  for(std::size_t v = 0; v < normals.size(); ++v)
  {
    const Vector n(columns[v][0], columns[v][1], columns[v][2]);
    normals[v] = split.empty() || n.squared_length() == 0 ? n : n / std::sqrt(n.squared_length());
  }
  return vectors_array(normals);
}

// The arrays given to fair(): the mesh, with its non-manifold vertices split for the run (n rows in and
// out, run_n vertices faired), and the attributes (d columns; one_column: given as one value per vertex).
struct Fair_input
{
  Mesh mesh;
  Vertex_split split;
  std::vector<std::string> changes;
  std::size_t run_n = 0, n = 0;
  py::array_t<double, py::array::c_style> attributes;
  bool one_column = false;
  py::ssize_t d = 0;
};

Fair_input read_arrays(py::handle V, py::handle F, py::handle attributes)
{
  Fair_input in;
  in.mesh = mesh_from_arrays(V, F, &in.split, &in.changes);
  in.run_n = in.mesh.number_of_vertices();
  in.n = in.split.empty() ? in.run_n : in.split.file_vertices;
  if(attributes.is_none()) return in;
  in.attributes = real_matrix(attributes, "attributes", py::ssize_t(in.n), -1);
  in.one_column = in.attributes.ndim() == 1;
  if(in.attributes.ndim() == 2 && in.attributes.shape(1) == 0) throw py::value_error("attributes has no column");
  in.d = in.one_column ? 1 : in.attributes.shape(1);
  return in;
}

// The attributes' values per vertex of the run, each finite (a copy of a split vertex has its vertex's).
std::vector<std::vector<double>> attribute_values(const Fair_input& in)
{
  const std::size_t d = std::size_t(in.d);
  std::vector<std::vector<double>> values(in.run_n, std::vector<double>(d));
  for(std::size_t i = 0; d > 0 && i < in.n; ++i)
    for(std::size_t c = 0; c < d; ++c)
    {
      values[i][c] = in.attributes.data()[i * d + c];
      if(!std::isfinite(values[i][c])) throw py::value_error("attributes row " + std::to_string(i) + " is not finite");
    }
  for(std::size_t i = 0; i < in.split.copy_of.size(); ++i) values[in.n + i] = values[in.split.copy_of[i]];
  return values;
}

// Whether each vertex of the run is held (a copy of a split vertex as its vertex), `count` of those given.
std::vector<unsigned char> held_vertices(py::handle vertex_is_constrained, const Fair_input& in, std::size_t& count)
{
  std::vector<unsigned char> held(in.run_n, 0);
  if(!vertex_is_constrained.is_none())
  {
    const auto h = real_matrix(vertex_is_constrained, "vertex_is_constrained", py::ssize_t(in.n), -1, true);
    if(h.ndim() != 1)
      throw py::value_error("vertex_is_constrained must be one value per vertex, not an array of " + describe(h));
    for(std::size_t i = 0; i < in.n; ++i) count += (held[i] = h.data()[i] != 0);
  }
  for(std::size_t i = 0; i < in.split.copy_of.size(); ++i) held[in.n + i] = held[in.split.copy_of[i]];
  return held;
}

// What the Python callback is given after a step.
py::dict step_info(const AF::Fairing_step& s)
{
  py::dict info;
  info["step"] = s.step;
  info["time"] = s.time;
  info["time_step"] = s.time_step;
  info["area"] = s.area;
  info["energy"] = s.energy;
  info["H_integral"] = s.H_integral;
  info["max_displacement"] = s.max_displacement;
  info["solver_iterations"] = s.solver_iterations;
  info["run"] = s.run;
  info["runs"] = s.runs;
  info["run_name"] = s.run_name;
  return info;
}

// The step callback of a run without the GIL. After every step it takes it: Python's signal handlers run
// there (Ctrl-C: KeyboardInterrupt), then the Python callback, if any. An exception either raises ends
// the library's call at once (Run_abandoned), kept in `raised` to be raised again afterwards.
Step_callback python_step(py::handle callback, std::exception_ptr& raised)
{
  const bool python_callback = !callback.is_none();
  return [callback, &raised, python_callback](const AF::Fairing_step& s) {
    py::gil_scoped_acquire gil;
    try
    {
      if(PyErr_CheckSignals() != 0) throw py::error_already_set();
      if(!python_callback) return true;
      const py::object go_on = callback(step_info(s));
      return go_on.is_none() || bool(py::bool_(go_on));   // None (a progress printer) goes on
    }
    catch(...)
    {
      raised = std::current_exception();
    }
    throw Run_abandoned();
  };
}

// The library's call without the GIL; an exception of the callback is raised again, nothing of the run
// kept (the input arrays were only read).
void run_fairing(Fair_input& in, const Options& o, AF::Attribute_mode mode, std::vector<std::vector<double>>& values,
                 std::vector<Point>& control_points, std::vector<unsigned char>& held, py::handle callback,
                 Run_record& r)
{
  std::exception_ptr raised;
  const Step_callback step = python_step(callback, raised);
  std::vector<std::vector<double>> controls = values;
  {
    py::gil_scoped_release no_gil;
    try
    {
      r.report = fair_with_options(in.mesh, o, mode, Attribute_vectors{&values}, controls, control_points, held, step);
    }
    catch(const Run_abandoned&)
    {
    }
    catch(const AF::Input_error& e)
    {
      py::gil_scoped_acquire gil;
      throw py::value_error(e.what());
    }
  }
  if(raised) std::rethrow_exception(raised);
  r.fairing_ran = true;
  if(!r.report.succeeded())
  {
    r.status = AF::to_string(r.report.status);
    r.message = r.report.message;
  }
}

// A failed run: FairingError, with the report attached.
[[noreturn]] void raise_failure(const Run_record& r, const py::object& report)
{
  py::object error = py::module_::import("anisotropic_fairing._core").attr("FairingError")(
      "fairing failed (" + r.status + "): " + (r.message.empty() ? std::string("no detail") : r.message));
  error.attr("report") = report;
  PyErr_SetObject(error.get_type().ptr(), error.ptr());
  throw py::error_already_set();
}

// The faired attributes in the shape given (None without).
py::object attributes_array(const Fair_input& in, const std::vector<std::vector<double>>& values)
{
  if(in.d == 0) return py::none();
  py::array_t<double> a = in.one_column ? py::array_t<double>({ py::ssize_t(in.n) })
                                        : py::array_t<double>({ py::ssize_t(in.n), in.d });
  double* p = a.mutable_data();
  for(std::size_t i = 0; i < in.n; ++i)
    for(py::ssize_t c = 0; c < in.d; ++c) p[i * std::size_t(in.d) + std::size_t(c)] = values[i][std::size_t(c)];
  return py::object(std::move(a));
}

// The report's name of the normals written
const char* normals_name(const Options& o, AF::Attribute_mode mode)
{
  if(mode == AF::Attribute_mode::ATTRIBUTES_ONLY) return "input";
  const AF::Fairing_options& f = o.fairing;
  const bool limit =
    f.finite_element == AF::Finite_element::LOOP && f.output_positions == AF::Output_positions::LIMIT_SURFACE;
  return limit ? "limit_surface" : "vertex_normals";
}

py::tuple fair(py::handle V, py::handle F, py::handle attributes, py::handle vertex_is_constrained, py::handle callback,
               bool vertex_normals, const py::kwargs& kwargs)
{
  CGAL::Real_timer wall;
  wall.start();
  Fair_input in = read_arrays(V, F, attributes);
  const Options o = options_of(kwargs, in.d);
  std::vector<std::vector<double>> values = attribute_values(in);
  Run_record r;
  std::vector<unsigned char> held = held_vertices(vertex_is_constrained, in, r.held_vertices);
  r.mesh_read = true;
  r.vertices = in.n;
  r.faces = in.mesh.number_of_faces();
  r.input_changes = in.changes;
  r.split_vertices = in.split.split_vertices;

  const AF::Attribute_mode mode = effective_mode(o);
  std::vector<Point> control_points(in.run_n);
  run_fairing(in, o, in.d > 0 ? mode : AF::Attribute_mode::GEOMETRY_ONLY, values, control_points, held, callback, r);
  merge_copies(in.mesh, in.split);
  merge_copies(values, in.split);
  py::object normals = py::none();
  if(vertex_normals && r.report.succeeded())
  {
    normals = written_normals(in.mesh, control_points, o, mode, in.split);
    r.normals = normals_name(o, mode);
  }
  const py::object report = json_loads(report_json(o, r, wall.time()));
  if(!r.report.succeeded()) raise_failure(r, report);
  const py::object out_attributes = attributes_array(in, values);
  if(vertex_normals) return py::make_tuple(points_array(in.mesh, in.n), out_attributes, report, normals);
  return py::make_tuple(points_array(in.mesh, in.n), out_attributes, report);
}

// ---- limit_surface() -------------------------------------------------------------------------------

// The Loop limit surface of a mesh given as arrays (it keeps its own copy of the mesh).
class Limit_surface
{
public:
  typedef AF::Loop_limit_surface<Mesh> Limit;

  Limit_surface(py::handle V, py::handle F, int quadrature_degree) : mesh_(new Mesh(mesh_from_arrays(V, F)))
  {
    try
    {
      limit_.reset(new Limit(*mesh_, AF::parameters::quadrature_degree(quadrature_degree)));
    }
    catch(const AF::Input_error& e)
    {
      throw py::value_error(e.what());
    }
  }

  py::array_t<double> positions() const
  {
    Mesh m = *mesh_;
    limit_->limit_positions(m.points());
    return points_array(m);
  }

  py::array_t<double> normals() const
  {
    std::vector<Vector> n(mesh_->number_of_vertices());
    limit_->limit_normals(CGAL::make_property_map(n));
    return vectors_array(n);
  }

  py::dict curvatures() const
  {
    std::vector<Limit::Curvature> c(mesh_->number_of_vertices());
    limit_->vertex_curvatures(CGAL::make_property_map(c));
    py::array_t<double> k1(py::ssize_t(c.size())), k2(py::ssize_t(c.size())), h(py::ssize_t(c.size()));
    std::vector<Vector> d1, d2;
    for(std::size_t i = 0; i < c.size(); ++i)
    {
      k1.mutable_data()[i] = c[i].k1;
      k2.mutable_data()[i] = c[i].k2;
      h.mutable_data()[i] = 0.5 * (c[i].k1 + c[i].k2);
      d1.push_back(c[i].d1);
      d2.push_back(c[i].d2);
    }
    py::dict out;
    out["k1"] = k1;
    out["k2"] = k2;
    out["mean_curvature"] = h;
    out["d1"] = vectors_array(d1);
    out["d2"] = vectors_array(d2);
    return out;
  }

  py::tuple resample(unsigned levels, py::handle attributes) const
  {
    Mesh fine;
    std::vector<std::vector<double>> in, out;
    bool one_column = false;
    py::ssize_t d = 0;
    if(!attributes.is_none())
    {
      const auto A = real_matrix(attributes, "attributes", py::ssize_t(mesh_->number_of_vertices()), -1);
      one_column = A.ndim() == 1;
      d = one_column ? 1 : A.shape(1);
      for(std::size_t i = 0; i < mesh_->number_of_vertices(); ++i)
        in.emplace_back(A.data() + i * std::size_t(d), A.data() + (i + 1) * std::size_t(d));
    }
    try
    {
      if(d == 0) limit_->resample(levels, fine);
      else
      {
        out.resize(mesh_->number_of_vertices() << (2 * std::min(levels, 10u)));   // more than enough rows
        limit_->resample(levels, fine, Attribute_vectors{&in}, Attribute_vectors{&out});
      }
    }
    catch(const AF::Input_error& e)
    {
      throw py::value_error(e.what());
    }
    py::array_t<long long> faces({ py::ssize_t(fine.number_of_faces()), py::ssize_t(3) });
    auto f = faces.mutable_unchecked<2>();
    for(Face_index face : fine.faces())
    {
      int c = 0;
      for(Vertex_index v : CGAL::vertices_around_face(fine.halfedge(face), fine))
        f(py::ssize_t(face), c++) = (long long)v;
    }
    if(d == 0) return py::make_tuple(points_array(fine), faces);
    const py::ssize_t nv = py::ssize_t(fine.number_of_vertices());
    py::array_t<double> a = one_column ? py::array_t<double>({ nv }) : py::array_t<double>({ nv, d });
    for(py::ssize_t i = 0; i < nv; ++i)
      for(py::ssize_t c = 0; c < d; ++c) a.mutable_data()[i * d + c] = out[std::size_t(i)][std::size_t(c)];
    return py::make_tuple(points_array(fine), faces, a);
  }

  double area() const { return limit_->area(); }

private:
  std::unique_ptr<Mesh> mesh_;   // the limit surface refers to it: it must not move
  std::unique_ptr<Limit> limit_;
};

} // namespace

PYBIND11_MODULE(_core, m)
{
  m.doc() = "The compiled part of the package anisotropic_fairing: use the package (import anisotropic_fairing).";
  m.attr("__version__") = AF_VERSION;
  // raised with the report attached (fair()); the C++ type only names it
  static py::exception<Fairing_failed> fairing_error(m, "FairingError", PyExc_RuntimeError);
  m.def("fair", &fair, py::arg("V"), py::arg("F"), py::kw_only(), py::arg("attributes") = py::none(),
        py::arg("vertex_is_constrained") = py::none(), py::arg("callback") = py::none(),
        py::arg("vertex_normals") = false,
        "fair(V, F, *, attributes=None, vertex_is_constrained=None, callback=None, vertex_normals=False, "
        "**parameters) -> (V2, attributes2, report), and with vertex_normals the normals the program writes "
        "(N x 3; None if the geometry was not faired) fourth: anisotropic_fairing.fair's run; its parameters "
        "(parameter_names) are checked here, as the program checks its options; Ctrl-C raises KeyboardInterrupt "
        "after the step it arrives in");
  py::tuple names(keywords().size());
  py::dict words;
  for(std::size_t k = 0; k < keywords().size(); ++k)
  {
    names[k] = py::str(keywords()[k].name);
    py::list taken;
    for(const char* w : keywords()[k].words) taken.append(py::str(w));
    if(!keywords()[k].words.empty()) words[names[k]] = py::tuple(taken);
  }
  m.attr("parameter_names") = names;   // the package's fair() takes these and passes them on
  m.attr("parameter_words") = words;   // the words of those that take words (the stubs' test)
  py::class_<Limit_surface>(m, "LimitSurface", "The Loop limit surface of a triangle mesh (see limit_surface()).")
      .def_property_readonly("positions", &Limit_surface::positions, "the limit points of the vertices (N x 3)")
      .def_property_readonly("normals", &Limit_surface::normals,
                             "the unit normals of the limit surface at the vertices (N x 3)")
      .def_property_readonly("area", &Limit_surface::area, "the area of the limit surface")
      .def("curvatures", &Limit_surface::curvatures,
           "dict: k1, k2 (principal curvatures, k1 <= k2, negative on a convex surface oriented outward), "
           "mean_curvature, d1, d2 (unit principal directions, N x 3), averaged over each vertex's faces "
           "(Loop_limit_surface::vertex_curvatures)")
      .def("resample", &Limit_surface::resample, py::arg("levels"), py::arg("attributes") = py::none(),
           "resample(levels, attributes=None) -> (V, F) or (V, F, attributes): the limit surface at 2^levels times the "
           "resolution (levels <= 10), every vertex on it, the mesh's vertices first; with attributes (N x d), "
           "their limit values");
  m.def("limit_surface",
        [](py::handle V, py::handle F, int quadrature_degree) { return Limit_surface(V, F, quadrature_degree); },
        py::arg("V"), py::arg("F"), py::kw_only(), py::arg("quadrature_degree") = 8,
        "limit_surface(V, F, *, quadrature_degree=8) -> LimitSurface: the Loop limit surface of the mesh, with limit "
        "positions, normals, curvatures and resample(levels)");
  // the names users meet, in tracebacks and help(): the package's
  for(const char* name : { "FairingError", "LimitSurface" }) m.attr(name).attr("__module__") = "anisotropic_fairing";
}
