// The per-vertex attributes of --attributes: the selected scalar components of the mesh's vertex
// properties (PLY numeric properties, colour channels, texture coordinates) are gathered, in the
// order given, into ONE std::vector<double> per vertex, so that the library faires all of them in one
// solve; the result is then scattered back into the original typed properties (integers rounded and
// clamped to their range, colour channels to 0..255 with alpha kept, floats as float).
#ifndef AF_TOOL_ATTRIBUTE_COLUMNS_H
#define AF_TOOL_ATTRIBUTE_COLUMNS_H

#include "mesh_io.h"
#include "tool_common.h"

#include <boost/property_map/property_map.hpp>

#include <functional>
#include <string>
#include <vector>

namespace af_tool {

// One scalar component of a vertex property, read and written as a double.
struct Attribute_column
{
  std::string name;
  std::function<double(Vertex_index)> get;
  std::function<void(Vertex_index, double)> set;
};

// The columns named by --attributes, in their order ("color" is red, green, blue; "uv" is u, v).
// Fails (exit 1, status attribute_error) on a name the input does not have.
std::vector<Attribute_column> resolve_attributes(Mesh& mesh, const Input_info& info, const std::string& input,
                                                 const std::vector<std::string>& names);

// All selected columns of a vertex as one vector: the attribute map given to the library.
struct Attribute_vectors
{
  typedef Vertex_index key_type;
  typedef std::vector<double> value_type;
  typedef const value_type& reference;
  typedef boost::read_write_property_map_tag category;
  std::vector<value_type>* values;   // indexed by the vertex index

  friend reference get(const Attribute_vectors& m, Vertex_index v) { return (*m.values)[std::size_t(v)]; }
  friend void put(const Attribute_vectors& m, Vertex_index v, const value_type& x) { (*m.values)[std::size_t(v)] = x; }
};

// The columns' values per vertex. `faired`: they are to be faired, so a NaN or infinite value fails
// (attribute_error, naming the attribute and the vertex); otherwise they are read as they are.
void gather(const Mesh& mesh, const std::vector<Attribute_column>& columns, std::vector<std::vector<double>>& values,
            bool faired = true);
void scatter(const Mesh& mesh, const std::vector<Attribute_column>& columns,
             const std::vector<std::vector<double>>& values);

} // namespace af_tool

#endif // AF_TOOL_ATTRIBUTE_COLUMNS_H
