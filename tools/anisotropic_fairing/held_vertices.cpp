#include "held_vertices.h"

#include <cstdint>
#include <fstream>
#include <sstream>

namespace af_tool {
namespace {

// held where the property "v:<name>" of type T is not 0; false if there is no such property of that type
template <typename T>
bool held_from_property(const Mesh& mesh, const std::string& name, std::vector<unsigned char>& held)
{
  const auto found = mesh.property_map<Vertex_index, T>("v:" + name);
  if(!found.second) return false;
  for(Vertex_index v : mesh.vertices()) held[std::size_t(v)] = found.first[v] != T(0) ? 1 : 0;
  return true;
}

template <typename... T>
bool held_from_any_property(const Mesh& mesh, const std::string& name, std::vector<unsigned char>& held)
{
  return (held_from_property<T>(mesh, name, held) || ...);
}

} // namespace

bool read_vertex_index_file(const std::string& spec, std::size_t vertices, const std::function<void(std::size_t)>& held)
{
  std::ifstream in(spec);
  if(!in) return false;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    std::string word, extra;
    if(!(words >> word) || word[0] == '#') continue;
    std::size_t used = 0;
    long long index = -1;
    try { index = std::stoll(word, &used); } catch(...) { used = 0; }
    if(used != word.size() || (words >> extra))
      fail("input_error",
           "--hold " + spec + ", line " + std::to_string(number) + ": '" + line + "' is not one vertex index");
    if(index < 0 || std::size_t(index) >= vertices)
      fail("input_error", "--hold " + spec + ", line " + std::to_string(number) + ": vertex " + word +
                            " does not exist (the input has " + std::to_string(vertices) +
                            " vertices, numbered from 0)");
    held(std::size_t(index));
  }
  return true;
}

std::size_t read_held_vertices(const Mesh& mesh, const std::string& spec, std::vector<unsigned char>& held)
{
  held.assign(mesh.number_of_vertices(), 0);
  if(!held_from_any_property<double, float, std::int8_t, std::uint8_t, std::int16_t, std::uint16_t, std::int32_t,
                             std::uint32_t, std::int64_t, std::uint64_t, bool>(mesh, spec, held) &&
     !read_vertex_index_file(spec, held.size(), [&held](std::size_t i) { held[i] = 1; }))
    fail("input_error",
         "--hold " + spec + ": neither a numeric vertex property of the input nor a readable file of vertex indices");
  std::size_t count = 0;
  for(unsigned char h : held) count += h;
  return count;
}

} // namespace af_tool
