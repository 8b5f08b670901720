// anisotropic_fairing tool: `--repair` (mesh_repair.h).

#include "mesh_repair.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>

#include <algorithm>
#include <map>

namespace af_tool {

namespace PMP = CGAL::Polygon_mesh_processing;

std::vector<std::string> repair_soup(Polygon_soup& soup)
{
  std::vector<std::string> changes;
  std::size_t dropped = 0;
  for(std::size_t f = 0; f < soup.faces.size();)
  {
    std::vector<std::size_t> sorted = soup.faces[f];
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) { ++f; continue; }
    soup.faces.erase(soup.faces.begin() + std::ptrdiff_t(f));
    soup.face_place.erase(soup.face_place.begin() + std::ptrdiff_t(f));
    ++dropped;
  }
  if(dropped) changes.push_back("removed " + std::to_string(dropped) + " faces that use one vertex twice");

  typedef Repair_mesh::Point Point;
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  const std::vector<std::vector<std::size_t> > before = soup.faces;
  const std::size_t n0 = points.size();
  PMP::orient_polygon_soup(points, soup.faces);   // false when it duplicated points, which is said below
  // a duplicated point stands for the file's vertex at the same place
  std::map<Point, std::size_t> original;
  for(std::size_t i = 0; i < n0; ++i) original.emplace(points[i], i);
  const auto is_rotation = [](const std::vector<std::size_t>& a, std::vector<std::size_t> b) {
    for(std::size_t k = 0; k < b.size(); ++k, std::rotate(b.begin(), b.begin() + 1, b.end()))
      if(a == b) return true;
    return false;
  };
  std::size_t reversed = 0;
  for(std::size_t f = 0; f < soup.faces.size(); ++f)
  {
    std::vector<std::size_t> after = soup.faces[f];
    for(std::size_t& v : after)
      if(v >= n0) v = original[points[v]];
    if(is_rotation(after, std::vector<std::size_t>(before[f].rbegin(), before[f].rend()))) ++reversed;
  }
  if(reversed) changes.push_back("reversed the orientation of " + std::to_string(reversed) + " faces to agree with their neighbours");
  if(points.size() > n0)
    changes.push_back("split non-manifold vertices and edges: " + std::to_string(points.size() - n0) +
                      " vertices duplicated (the new ones are written after the input's " + std::to_string(n0) + ")");
  soup.points.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) soup.points[i] = {points[i].x(), points[i].y(), points[i].z()};
  soup.face_place.resize(soup.faces.size(), "a repaired face");
  return changes;
}

std::vector<std::string> repair_mesh(Repair_mesh& mesh)
{
  std::vector<std::string> changes;
  const std::size_t before = mesh.number_of_vertices();
  const std::size_t stitched = PMP::stitch_borders(mesh);
  if(stitched)
    changes.push_back("stitched " + std::to_string(stitched) + " pairs of coinciding border edges (" +
                      std::to_string(before - mesh.number_of_vertices()) + " vertices merged into the ones they coincide with)");
  const std::size_t isolated = PMP::remove_isolated_vertices(mesh);
  if(isolated) changes.push_back("removed " + std::to_string(isolated) + " vertices on no face");
  if(mesh.has_garbage())
  {
    mesh.collect_garbage();   // the vertices after a removed one move up
    changes.push_back("the vertices after the removed ones move up: the output's vertex numbers differ from the input's");
  }
  return changes;
}

} // namespace af_tool
