// anisotropic_fairing tool: the properties of one vertex or face given to another, whatever their names,
// for the types the program reads and writes (numbers, colours, vectors, texture coordinates): a vertex
// split for the run gets its original's, a triangle cut from a polygon its polygon's.
#ifndef AF_TOOL_ELEMENT_PROPERTIES_H
#define AF_TOOL_ELEMENT_PROPERTIES_H

#include "mesh_io.h"

#include <string>

namespace af_tool {

// Surface_mesh's own maps (connectivity, removal marks), which are not properties of the file
inline bool is_internal_property(const std::string& name)
{
  return name == "v:connectivity" || name == "v:point" || name == "v:removed" || name == "f:connectivity" ||
         name == "f:removed" || name == "e:removed" || name == "h:connectivity";
}

// Calls f(map) for the property `name` of elements `Index` if it has one of the program's types.
template <typename Index, typename F>
bool with_property_map(Mesh& mesh, const std::string& name, F&& f)
{
  const auto as = [&](auto zero) {
    auto map = mesh.property_map<Index, decltype(zero)>(name);
    if(map.second) f(map.first);
    return map.second;
  };
  return for_numeric_type(as) || as(CGAL::IO::Color()) || as(Vector()) || as(Texcoord());
}

// Every property of element `to` set to element `from`'s.
template <typename Index>
void copy_properties(Mesh& mesh, Index from, Index to)
{
  for(const std::string& name : mesh.properties<Index>())
    if(!is_internal_property(name)) with_property_map<Index>(mesh, name, [&](auto& map) { map[to] = map[from]; });
}

} // namespace af_tool

#endif // AF_TOOL_ELEMENT_PROPERTIES_H
