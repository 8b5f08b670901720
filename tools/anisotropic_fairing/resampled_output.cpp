// --resample K (see resampled_output.h).
#include "resampled_output.h"

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/internal/run/Memory_estimate.h>
#include <CGAL/IO/Color.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace af_tool {

namespace {

typedef AF::Loop_limit_surface<Mesh> Limit;
typedef std::vector<double> Values;

// An output map of Loop_limit_surface::resample: one value per new vertex, grown as they come.
template <typename T>
struct Growing_map
{
  typedef Vertex_index key_type;
  typedef T value_type;
  typedef const T& reference;
  typedef boost::read_write_property_map_tag category;
  std::vector<T>* values;

  friend reference get(const Growing_map& m, Vertex_index v) { return (*m.values)[std::size_t(v)]; }
  friend void put(const Growing_map& m, Vertex_index v, const T& x)
  {
    if(std::size_t(v) >= m.values->size()) m.values->resize(std::size_t(v) + 1);
    (*m.values)[std::size_t(v)] = x;
  }
};

bool is_curvature_property(const std::string& p) { return p == "v:k1" || p == "v:k2" || p == "v:mean_curvature"; }

// The names (as --attributes takes them) of every vertex property that is a function on the surface.
std::vector<std::string> function_properties(const Mesh& mesh, const Input_info& info, bool curvature)
{
  std::vector<std::string> names;
  for(const std::string& p : mesh.properties<Vertex_index>())
    if(p.compare(0, 2, "v:") == 0 && is_numeric_property<Vertex_index>(mesh, p) &&
       !(curvature && is_curvature_property(p)))
      names.push_back(p.substr(2));
  if(mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color").second)
  {
    for(const char* c : {"red", "green", "blue"}) names.push_back(c);
    if(info.vertex_alpha) names.push_back("alpha");
  }
  if(mesh.property_map<Vertex_index, Texcoord>("v:texcoord").second) names.push_back("uv");
  return names;
}

// Adds to `to` the property `name` of `from` (key Index) with its type, if it is one of `Types`.
template <typename Index, typename... Types>
bool add_same_property(const Mesh& from, Mesh& to, const std::string& name)
{
  bool added = false;
  (void)std::initializer_list<int>{ (added = added || (from.property_map<Index, Types>(name).second &&
                                                       (to.add_property_map<Index, Types>(name, Types()), true)),
                                     0)... };
  return added;
}

template <typename Index, typename T>
bool copy_values(const Mesh& from, Mesh& to, const std::string& name, const std::vector<Index>& source)
{
  const auto in = from.property_map<Index, T>(name);
  if(!in.second) return false;
  auto out = to.property_map<Index, T>(name).first;
  for(std::size_t i = 0; i < source.size(); ++i) out[Index(i)] = in.first[source[i]];
  return true;
}

// Copies property `name` from the elements `source[i]` of `from` to the elements i of `to`.
template <typename Index>
void copy_property(const Mesh& from, Mesh& to, const std::string& name, const std::vector<Index>& source)
{
  for_numeric_type([&](auto zero) { return copy_values<Index, decltype(zero)>(from, to, name, source); }) ||
    copy_values<Index, CGAL::IO::Color>(from, to, name, source) || copy_values<Index, Vector>(from, to, name, source) ||
    copy_values<Index, Texcoord>(from, to, name, source);
}

// Adds to `to` every property of `from` with key Index, of a type the files hold; returns their names.
template <typename Index>
std::vector<std::string> add_properties(const Mesh& from, Mesh& to, const char* prefix)
{
  std::vector<std::string> names;
  for(const std::string& p : from.properties<Index>())
  {
    if(p.compare(0, 2, prefix) != 0 || to.property_map<Index, Point>(p).second) continue;   // v:point
    if(add_same_property<Index, boost::int8_t, boost::uint8_t, boost::int16_t, boost::uint16_t, boost::int32_t,
                         boost::uint32_t, boost::int64_t, boost::uint64_t, float, double, CGAL::IO::Color, Vector,
                         Texcoord>(from, to, p))
      names.push_back(p);
  }
  return names;
}

// The control values of every function on the surface: the faired attributes by their faired control
// values, the others by their values. A property holding NaN or infinity (never a faired one) has no limit
// where those values reach: resampled with 0 in their place and beside it their indicator, whose limit is
// positive exactly where they reach (Loop's weights are positive), NaN is written there.
std::vector<Values> function_controls(const std::vector<Attribute_column>& columns, const std::vector<Values>& written,
                                      const Faired_controls& faired)
{
  std::vector<Values> controls = written;
  for(std::size_t c = 0; c < columns.size(); ++c)
    for(std::size_t f = 0; f < faired.columns->size(); ++f)
      if(columns[c].name == (*faired.columns)[f].name)
        for(std::size_t i = 0; i < controls.size(); ++i) controls[i][c] = (*faired.values)[i][f];
  const std::size_t d = columns.size();
  for(Values& row : controls) row.resize(2 * d, 0.0);
  for(Values& row : controls)
    for(std::size_t c = 0; c < d; ++c)
      if(!std::isfinite(row[c])) { row[c] = 0; row[d + c] = 1; }
  return controls;
}

// `fine`: the limit surface of `control` at `levels` levels, its normals (if the input has normals), its
// curvature (with --curvature) and, in `values`, the limits of the functions' control values.
void resample_limit(const Mesh& control, unsigned levels, const Input_info& info, bool curvature,
                    int quadrature_degree, bool with_functions, std::vector<Values>& controls, Mesh& fine,
                    std::vector<Values>& values)
{
  const Limit limit(control, AF::parameters::quadrature_degree(curvature ? quadrature_degree : 4));
  std::vector<Limit::Curvature> curvatures;
  const Growing_map<Limit::Curvature> curvature_map{&curvatures};
  // removed below if the input has none
  auto normals = fine.add_property_map<Vertex_index, Vector>("v:normal").first;
  auto resample = [&](const auto& np) {
    if(!with_functions) limit.resample(levels, fine, np);
    else limit.resample(levels, fine, Attribute_vectors{&controls}, Growing_map<Values>{&values}, np);
  };
  const auto with_normals = AF::parameters::vertex_normal_map(normals);
  // the curvature only when asked: it costs a quadrature pass
  if(curvature) resample(with_normals.vertex_curvature_map(curvature_map));
  else resample(with_normals);
  if(!info.has_normals) fine.remove_property_map(normals);
  if(!curvature) return;
  auto k1 = fine.property_map<Vertex_index, double>("v:k1").first;
  auto k2 = fine.property_map<Vertex_index, double>("v:k2").first;
  auto h = fine.property_map<Vertex_index, double>("v:mean_curvature").first;
  for(Vertex_index v : fine.vertices())
  {
    const Limit::Curvature& c = curvatures[std::size_t(v)];
    k1[v] = c.k1;
    k2[v] = c.k2;
    h[v] = 0.5 * (c.k1 + c.k2);
  }
}

} // namespace

void check_resample_size(const Mesh& mesh, unsigned levels, const std::optional<double>& memory_limit)
{
  const double faces = double(mesh.number_of_faces()) * std::pow(4.0, double(levels));
  if(faces > resample_face_budget)
  {
    char text[200];
    std::snprintf(text, sizeof text,
                  "--resample %u would write %.3g faces (%zu x 4^%u), more than the %.3g this program writes", levels,
                  faces, std::size_t(mesh.number_of_faces()), levels, resample_face_budget);
    fail("invalid_parameter", text);
  }
  // the resampled mesh, its properties and the limit evaluation: 206 bytes a written face, measured on the
  // Loop-refined fertility at 2 and 3 levels (bench/memory_estimate.py's meshes)
  const double need = 210.0 * faces;
  const AF::internal::Available_memory available = AF::internal::available_memory(memory_limit);
  if(need > available.bytes)
    fail("insufficient_memory",
         "--resample " + std::to_string(levels) + " writes " + std::to_string(std::size_t(faces)) +
           " faces, which need about " + AF::internal::megabytes(need) + " of memory, and " +
           AF::internal::megabytes(available.bytes) + " are available (" + available.source +
           "); nothing was done: --memory-limit sets what the run may take, off writes them without this check");
}

void resample_output(Mesh& mesh, const Input_info& info, const std::string& input, unsigned levels,
                     const Faired_controls& faired, bool curvature, int quadrature_degree)
{
  // the limit surface of the faired control points
  Mesh control = mesh;
  for(Vertex_index v : control.vertices()) control.point(v) = (*faired.points)[std::size_t(v)];

  Mesh& coarse = mesh;
  const std::vector<Attribute_column> columns =
      resolve_attributes(coarse, info, input, function_properties(coarse, info, curvature));
  std::vector<Values> written;
  gather(coarse, columns, written, false);
  std::vector<Values> controls = function_controls(columns, written, faired);
  const std::size_t d = columns.size();

  Mesh fine;
  const std::vector<std::string> vertex_properties = add_properties<Vertex_index>(coarse, fine, "v:");
  const std::vector<std::string> face_properties = add_properties<Face_index>(coarse, fine, "f:");
  std::vector<Values> values;
  resample_limit(control, levels, info, curvature, quadrature_degree, !columns.empty(), controls, fine, values);

  // the input's vertices as the run without --resample writes them, every property included
  const std::size_t n = coarse.number_of_vertices();
  values.resize(fine.number_of_vertices());
  std::vector<Vertex_index> same(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    same[i] = Vertex_index(Mesh::size_type(i));
    fine.point(same[i]) = coarse.point(same[i]);
    values[i] = written[i];
  }
  for(std::size_t i = n; i < values.size(); ++i)
  {
    for(std::size_t c = 0; c < d; ++c)
      if(values[i][d + c] > 0) values[i][c] = std::numeric_limits<double>::quiet_NaN();
    values[i].resize(d);
  }
  for(const std::string& p : vertex_properties) copy_property(coarse, fine, p, same);
  scatter(fine, resolve_attributes(fine, info, input, function_properties(coarse, info, curvature)), values);

  // a new face: the properties of the input face it lies in (4^levels per face, in the order of faces())
  const std::vector<Face_index> input_faces(coarse.faces().begin(), coarse.faces().end());
  std::vector<Face_index> parent(fine.number_of_faces());
  for(std::size_t k = 0; k < parent.size(); ++k) parent[k] = input_faces[k >> (2 * levels)];
  for(const std::string& p : face_properties) copy_property(coarse, fine, p, parent);

  mesh = std::move(fine);
}

} // namespace af_tool
