// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// --attributes on a part (Part_run.cpp): the columns named, among the vertex properties of a file read by blocks
// (Ply_blocks.h), as the serial program selects them (attribute_columns.cpp: a numeric property by its name;
// color: red, green, blue), their values at the part's vertices fetched from the holders of the blocks
// (Part_values.h), and the faired values put back in each property's type as the serial program puts them
// (Vector_attribute_traits: integers rounded and clamped to their range, floats rounded to float).
// A name the parts cannot resolve so (uv, a colour not of bytes, a name the file lacks, one chosen twice) leaves
// the run to the whole mesh, whose reader says what the serial program says.

#ifndef AF_DISTRIBUTED_PART_ATTRIBUTES_H
#define AF_DISTRIBUTED_PART_ATTRIBUTES_H

#include "Mesh_part.h"
#include "Part_values.h"
#include "Ply_blocks.h"
#include "options.h"

#include <CGAL/Anisotropic_fairing/Vector_attribute_traits.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace af_distributed {

/// The attribute columns of a part: each an index into the blocks' property names.
struct Part_attributes
{
  std::vector<std::size_t> columns;
  std::vector<std::vector<double>> values, controls;   // per vertex of the part: the columns' values
  bool faired() const { return !columns.empty(); }
};

/// The columns `o.attributes` names among `blocks.names`, in the serial program's order; false where the parts
/// cannot resolve them as it does.
inline bool resolve_part_attributes(const af_tool::Options& o, const Ply_blocks& blocks,
                                    std::vector<std::size_t>& columns)
{
  columns.clear();
  const Ply_element& vertex = blocks.header.elements[std::size_t(blocks.header.vertex)];
  const auto column = [&](const std::string& name, bool byte) {
    const auto at = std::find(blocks.names.begin(), blocks.names.end(), name);
    if(at == blocks.names.end()) return false;
    const std::size_t k = std::size_t(at - blocks.names.begin());
    if(byte && vertex.properties[std::size_t(blocks.header.columns[k])].type != Ply_type::uint8) return false;
    columns.push_back(k);
    return true;
  };
  for(const std::string& name : o.attributes)
  {
    const bool colour = name == "red" || name == "green" || name == "blue" || name == "alpha";
    if(name == "x" || name == "y" || name == "z" || name == "nx" || name == "ny" || name == "nz" || name == "uv" ||
       name == "normal")
      return false;
    const bool found =
      name == "color" ? column("red", true) && column("green", true) && column("blue", true) : column(name, colour);
    if(!found) return false;
  }
  std::vector<std::size_t> sorted = columns;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

/// The part's values of the columns (collective); a faired value that is not finite fails as the serial program
/// fails, naming the vertex by its number in the file.
inline void gather_part_attributes(MPI_Comm comm, const Ply_blocks& blocks, const Mesh_part& part, Part_attributes& a)
{
  const std::vector<double> all = part_values(comm, blocks, part);
  const std::size_t width = blocks.names.size();
  a.values.assign(part.global_vertex.size(), std::vector<double>(a.columns.size()));
  for(std::size_t v = 0; v < a.values.size(); ++v)
    for(std::size_t c = 0; c < a.columns.size(); ++c)
    {
      const double x = all[v * width + a.columns[c]];
      if(v < part.owned_vertices && !std::isfinite(x))
        af_tool::fail("attribute_error", "--attributes " + blocks.names[a.columns[c]] + ": vertex " +
                                           std::to_string(part.global_vertex[v]) + " holds " +
                                           (std::isnan(x) ? "NaN" : "an infinite value") + ", which cannot be faired");
      a.values[v][c] = x;
    }
  a.controls = a.values;
}

/// `x` as a property of type `t` holds it, as the serial program writes a faired value back
inline double in_property_type(Ply_type t, double x)
{
  namespace AF = CGAL::Anisotropic_fairing;
  switch(t)
  {
    case Ply_type::int8: return double(AF::Vector_attribute_traits<std::int8_t>::make(0, &x));
    case Ply_type::uint8: return double(AF::Vector_attribute_traits<std::uint8_t>::make(0, &x));
    case Ply_type::int16: return double(AF::Vector_attribute_traits<std::int16_t>::make(0, &x));
    case Ply_type::uint16: return double(AF::Vector_attribute_traits<std::uint16_t>::make(0, &x));
    case Ply_type::int32: return double(AF::Vector_attribute_traits<std::int32_t>::make(0, &x));
    case Ply_type::uint32: return double(AF::Vector_attribute_traits<std::uint32_t>::make(0, &x));
    case Ply_type::float32: return double(float(x));
    default: return x;
  }
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PART_ATTRIBUTES_H
