// The attribute columns of --attributes (see attribute_columns.h).
#include "attribute_columns.h"

#include <CGAL/Anisotropic_fairing/Vector_attribute_traits.h>
#include <CGAL/IO/Color.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace af_tool {

namespace {

// A numeric vertex property v:<name>; integers are rounded and clamped when written, floats rounded to float.
bool add_numeric_column(Mesh& mesh, const std::string& name, std::vector<Attribute_column>& columns)
{
  return for_numeric_type([&](auto zero) {
    typedef decltype(zero) T;
    Mesh::Property_map<Vertex_index, T> map;
    bool found = false;
    std::tie(map, found) = mesh.property_map<Vertex_index, T>("v:" + name);
    if(!found) return false;
    columns.push_back(
      { name, [map](Vertex_index v) { return double(get(map, v)); },
        [map](Vertex_index v, double x) { put(map, v, AF::Vector_attribute_traits<T>::make(get(map, v), &x)); } });
    return true;
  });
}

// Channel c (0 red .. 3 alpha) of v:color; the others are kept.
Attribute_column color_column(Mesh::Property_map<Vertex_index, CGAL::IO::Color> map, const std::string& name,
                              std::size_t c)
{
  return {name, [map, c](Vertex_index v) { return double(get(map, v)[c]); },
          [map, c](Vertex_index v, double x) {
            CGAL::IO::Color color = get(map, v);
            color[c] = !(x > 0) ? (unsigned char)0 : (unsigned char)std::lround((std::min)(x, 255.0));   // NaN -> 0
            put(map, v, color);
          }};
}

Attribute_column texcoord_column(Texcoord_map map, const std::string& name, int c)
{
  return {name, [map, c](Vertex_index v) { return get(map, v)[c]; },
          [map, c](Vertex_index v, double x) {
            const Texcoord p = get(map, v);
            put(map, v, c == 0 ? Texcoord(x, p.y()) : Texcoord(p.x(), x));
          }};
}

// The names --attributes accepts for this mesh.
std::vector<std::string> available_attributes(const Mesh& mesh, const Input_info& info)
{
  std::vector<std::string> names;
  for(const std::string& p : mesh.properties<Vertex_index>())
    if(p.compare(0, 2, "v:") == 0 && is_numeric_property<Vertex_index>(mesh, p)) names.push_back(p.substr(2));
  if(mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color").second)
  {
    for(const char* n : {"red", "green", "blue"}) names.push_back(n);
    if(info.vertex_alpha) names.push_back("alpha");
    names.push_back("color");
  }
  if(mesh.property_map<Vertex_index, Texcoord>("v:texcoord").second) names.push_back("uv");
  return names;
}

} // namespace

// The columns named by --attributes, in their order ("color" is red, green, blue; "uv" is u, v).
// Fails (exit 1, status attribute_error) on a name the input does not have.
std::vector<Attribute_column> resolve_attributes(Mesh& mesh, const Input_info& info, const std::string& input,
                                                 const std::vector<std::string>& names)
{
  std::vector<Attribute_column> columns;
  Mesh::Property_map<Vertex_index, CGAL::IO::Color> color;
  bool has_color = false;
  std::tie(color, has_color) = mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color");
  Texcoord_map uv;
  bool has_uv = false;
  std::tie(uv, has_uv) = mesh.property_map<Vertex_index, Texcoord>("v:texcoord");
  for(const std::string& name : names)
  {
    const std::string what = "--attributes " + name + ": ";
    if(name == "x" || name == "y" || name == "z")
      fail("attribute_error",
           what + "a vertex coordinate, not an attribute (--mode says whether the geometry is faired)");
    if(name == "nx" || name == "ny" || name == "nz" || name == "normal")
      fail("attribute_error", what + "vertex normals are not faired: the normals of the faired surface are written");
    if(add_numeric_column(mesh, name, columns)) continue;
    if(has_color && (name == "red" || name == "green" || name == "blue" || name == "color" ||
                     (name == "alpha" && info.vertex_alpha)))
    {
      if(name == "red" || name == "color") columns.push_back(color_column(color, "red", 0));
      if(name == "green" || name == "color") columns.push_back(color_column(color, "green", 1));
      if(name == "blue" || name == "color") columns.push_back(color_column(color, "blue", 2));
      if(name == "alpha") columns.push_back(color_column(color, "alpha", 3));
      continue;
    }
    if(has_uv && name == "uv")
    {
      columns.push_back(texcoord_column(uv, "u", 0));
      columns.push_back(texcoord_column(uv, "v", 1));
      continue;
    }
    if(name == "uv" && !info.uv_problem.empty()) fail("attribute_error", what + info.uv_problem);
    std::string list;
    for(const std::string& a : available_attributes(mesh, info)) list += (list.empty() ? "" : ", ") + a;
    fail("attribute_error", what + input + " has no such vertex attribute (available: " +
                            (list.empty() ? std::string("none") : list) + ")");
  }
  for(std::size_t i = 0; i < columns.size(); ++i)
    for(std::size_t j = 0; j < i; ++j)
      if(columns[i].name == columns[j].name)
        fail("attribute_error", "--attributes selects " + columns[i].name + " twice (color is red,green,blue)");
  return columns;
}

void gather(const Mesh& mesh, const std::vector<Attribute_column>& columns, std::vector<std::vector<double>>& values,
            bool faired)
{
  values.assign(mesh.num_vertices(), std::vector<double>(columns.size()));
  for(Vertex_index v : mesh.vertices())
    for(std::size_t c = 0; c < columns.size(); ++c)
    {
      const double x = columns[c].get(v);
      // a property that is not faired may hold anything (it is written as it was); a faired one may not
      if(faired && !std::isfinite(x))
        fail("attribute_error", "--attributes " + columns[c].name + ": vertex " + std::to_string(std::size_t(v)) +
                                  " holds " + (std::isnan(x) ? "NaN" : "an infinite value") +
                                  ", which cannot be faired");
      values[std::size_t(v)][c] = x;
    }
}

void scatter(const Mesh& mesh, const std::vector<Attribute_column>& columns,
             const std::vector<std::vector<double>>& values)
{
  for(Vertex_index v : mesh.vertices())
    for(std::size_t c = 0; c < columns.size(); ++c) columns[c].set(v, values[std::size_t(v)][c]);
}

} // namespace af_tool
