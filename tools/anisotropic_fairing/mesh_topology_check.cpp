// anisotropic_fairing tool: whether a polygon soup's faces form an oriented 2-manifold, and if not,
// which element does not (CGAL's readers only say that building the mesh failed).

#include "mesh_file_check.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace af_tool {

namespace {

// union-find over the face corners
std::size_t root(std::vector<std::size_t>& parent, std::size_t i)
{
  while(parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

struct Half_edge { std::size_t low, high, face, k; bool forward; };   // forward: runs from low to high

// Sorted by (low, high, face): placed by low (in face order), then each vertex's few sorted by high, stably.
void sort_by_vertices(std::vector<Half_edge>& edges, std::size_t vertices)
{
  std::vector<std::size_t> at(vertices + 1, 0);
  for(const Half_edge& e : edges) ++at[e.low + 1];
  std::partial_sum(at.begin(), at.end(), at.begin());
  std::vector<Half_edge> placed(edges.size());
  for(const Half_edge& e : edges) placed[at[e.low]++] = e;
  edges.swap(placed);
  for(std::size_t v = 0, begin = 0; v < vertices; begin = at[v++])
    for(std::size_t i = begin + 1; i < at[v]; ++i)   // insertion: a vertex has a few
    {
      const Half_edge x = edges[i];
      std::size_t j = i;
      for(; j > begin && edges[j - 1].high > x.high; --j) edges[j] = edges[j - 1];
      edges[j] = x;
    }
}

} // namespace

void check_oriented_manifold(const Polygon_soup& soup)
{
  const auto& faces = soup.faces;
  // places are "line 12" (text) or "face 7", "triangle 3 of strip 0" (binary)
  const auto face_name = [&](std::size_t f) {
    const std::string& place = soup.face_place[f];
    return place.compare(0, 5, "line ") == 0 ? "face " + std::to_string(f) + " (" + place + ")" : place;
  };
  const auto fail = [&](const std::string& what) { throw File_problem(soup.path + ": " + what); };
  std::vector<std::size_t> first_corner(faces.size() + 1, 0);
  for(std::size_t f = 0; f < faces.size(); ++f) first_corner[f + 1] = first_corner[f] + faces[f].size();

  std::vector<Half_edge> edges;
  edges.reserve(first_corner.back());
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    const auto& face = faces[f];
    for(std::size_t k = 0; k < face.size(); ++k)
    {
      const std::size_t a = face[k], b = face[(k + 1) % face.size()];
      if(std::count(face.begin(), face.end(), a) > 1)
        fail(face_name(f) + " uses vertex " + std::to_string(a) + " twice");
      edges.push_back({std::min(a, b), std::max(a, b), f, k, a < b});
    }
  }
  sort_by_vertices(edges, soup.points.size());

  std::vector<std::size_t> parent(first_corner.back());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto corner = [&](std::size_t f, std::size_t k) { return first_corner[f] + k % faces[f].size(); };
  for(std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i + 1;
    while(j < edges.size() && edges[j].low == edges[i].low && edges[j].high == edges[i].high) ++j;
    const auto edge = [&] {
      return "the edge between vertices " + std::to_string(edges[i].low) + " and " + std::to_string(edges[i].high);
    };
    if(j - i > 2)
      fail(edge() + " is shared by " + std::to_string(j - i) + " faces (" + face_name(edges[i].face) + ", " +
           face_name(edges[i + 1].face) + ", " + face_name(edges[i + 2].face) + (j - i > 3 ? ", ..." : "") +
           "): the mesh is not a 2-manifold");
    if(j - i == 2)
    {
      const Half_edge& x = edges[i];
      const Half_edge& y = edges[i + 1];
      if(x.forward == y.forward)
        fail(face_name(x.face) + " and " + face_name(y.face) + " both run from vertex " +
             std::to_string(x.forward ? x.low : x.high) + " to vertex " + std::to_string(x.forward ? x.high : x.low) +
             ": their orientations disagree (one of them is flipped)");
      // the two faces meet at both ends of the edge: their corners there are in one fan
      parent[root(parent, corner(x.face, x.k))] = root(parent, corner(y.face, y.k + 1));
      parent[root(parent, corner(x.face, x.k + 1))] = root(parent, corner(y.face, y.k));
    }
    i = j;
  }
  // a vertex whose corners do not form one fan (a bow-tie)
  std::vector<std::size_t> fan(soup.points.size(), parent.size());
  std::vector<std::size_t> fan_face(soup.points.size(), 0);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(std::size_t k = 0; k < faces[f].size(); ++k)
    {
      const std::size_t v = faces[f][k], r = root(parent, corner(f, k));
      if(fan[v] == parent.size()) { fan[v] = r; fan_face[v] = f; }
      else if(fan[v] != r)
        fail("vertex " + std::to_string(v) + " is non-manifold: its faces form separate fans (" +
             face_name(fan_face[v]) + " and " + face_name(f) + " meet only there, as in a bow-tie)");
    }
}

} // namespace af_tool
