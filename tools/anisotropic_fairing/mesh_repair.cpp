// anisotropic_fairing tool: repairs of the input (mesh_repair.h).

#include "mesh_repair.h"

#include "element_properties.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <algorithm>

namespace af_tool {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// How orient_polygon_soup changed a face: `after` is `before` or its reverse, up to a rotation, with some
// points replaced by copies at the same place. Sets copy_of for those copies; returns whether reversed.
bool match_face(const std::vector<std::size_t>& before, const std::vector<std::size_t>& after, std::size_t n0,
                const std::vector<Point>& points, std::vector<std::size_t>& copy_of)
{
  const std::size_t m = before.size();
  for(int reversed = 0; reversed < 2; ++reversed)
    for(std::size_t r = 0; r < m; ++r)
    {
      const auto at = [&](std::size_t i) { return before[reversed ? (r + m - i) % m : (r + i) % m]; };
      bool same = true;
      for(std::size_t i = 0; i < m && same; ++i)
        same = after[i] == at(i) || (after[i] >= n0 && points[after[i]] == points[at(i)]);
      if(!same) continue;
      for(std::size_t i = 0; i < m; ++i)
        if(after[i] >= n0) copy_of[after[i] - n0] = at(i);
      return reversed == 1;
    }
  return false;   // not reached: orient_polygon_soup only reverses faces and replaces points by copies
}

} // namespace

Soup_repair repair_soup(Polygon_soup& soup)
{
  Soup_repair result;
  std::size_t dropped = 0;
  std::vector<std::vector<std::size_t> > kept;
  std::vector<std::string> kept_place;
  for(std::size_t f = 0; f < soup.faces.size(); ++f)
  {
    std::vector<std::size_t> sorted = soup.faces[f];
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) { ++dropped; continue; }
    kept.push_back(std::move(soup.faces[f]));
    kept_place.push_back(std::move(soup.face_place[f]));
  }
  soup.faces.swap(kept);
  soup.face_place.swap(kept_place);
  if(dropped) result.changes.push_back("removed " + std::to_string(dropped) + " faces that use one vertex twice");

  std::vector<Point> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  const std::vector<std::vector<std::size_t> > before = soup.faces;
  const std::size_t n0 = points.size();
  PMP::orient_polygon_soup(points, soup.faces);   // false when it duplicated points, which is said below
  result.copy_of.assign(points.size() - n0, 0);
  std::size_t reversed = 0;
  for(std::size_t f = 0; f < soup.faces.size(); ++f)
    if(before[f] != soup.faces[f]) reversed += match_face(before[f], soup.faces[f], n0, points, result.copy_of);
  if(reversed)
    result.changes.push_back("reversed the orientation of " + std::to_string(reversed) +
                             " faces to agree with their neighbours");
  if(points.size() > n0)
  {
    std::vector<std::size_t> originals = result.copy_of;
    std::sort(originals.begin(), originals.end());
    result.split_vertices = std::size_t(std::unique(originals.begin(), originals.end()) - originals.begin());
    const bool one = result.split_vertices == 1;
    result.changes.push_back(
      "split " + std::to_string(result.split_vertices) + " non-manifold vert" + (one ? "ex" : "ices") + " (" +
      (one ? "" : "the first: ") + "vertex " + std::to_string(originals.front()) +
      "; an edge of more than two faces is split at its ends) into " +
      std::to_string(result.split_vertices + points.size() - n0) + " vertices, one per fan of faces");
  }
  soup.points.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) soup.points[i] = {points[i].x(), points[i].y(), points[i].z()};
  return result;
}

std::vector<std::string> repair_mesh(Mesh& mesh)
{
  std::vector<std::string> changes;
  const std::size_t before = mesh.number_of_vertices();
  const std::size_t stitched = PMP::stitch_borders(mesh);
  if(stitched)
    changes.push_back("stitched " + std::to_string(stitched) + " pairs of coinciding border edges (" +
                      std::to_string(before - mesh.number_of_vertices()) +
                      " vertices merged into the ones they coincide with)");
  const std::size_t isolated = PMP::remove_isolated_vertices(mesh);
  if(isolated) changes.push_back("removed " + std::to_string(isolated) + " vertices on no face");
  if(mesh.has_garbage())
  {
    mesh.collect_garbage();   // the vertices after a removed one move up, with their properties
    changes.push_back(
      "the vertices after the removed ones move up: the output's vertex numbers differ from the input's");
  }
  return changes;
}

namespace {

// gives each triangle cut from a polygon the polygon's face properties (the visitor is copied: a pointer)
struct Keep_face_properties
{
  Mesh* mesh;
  Face_index polygon;
  void before_subface_creations(Face_index f) { polygon = f; }
  void after_subface_created(Face_index f) { if(f != polygon) copy_properties(*mesh, polygon, f); }
  void after_subface_creations() {}
};

} // namespace

std::size_t triangulate_polygons(Mesh& mesh)
{
  std::size_t polygons = 0;
  for(Face_index f : mesh.faces()) polygons += mesh.degree(f) > 3;
  if(polygons == 0) return 0;
  // a polygon triangulated by a constrained Delaunay triangulation is removed first: its slot must keep its
  // properties (not be recycled, which resets them) until its triangles have them, then it is collected
  const bool recycle = mesh.does_recycle_garbage();
  mesh.set_recycle_garbage(false);
  const bool done = PMP::triangulate_faces(mesh, CGAL::parameters::visitor(Keep_face_properties{&mesh, Face_index()}));
  mesh.set_recycle_garbage(recycle);
  if(!done) fail("input_error", "cannot triangulate the polygons of the input (CGAL's triangulate_faces failed)");
  if(mesh.has_garbage()) mesh.collect_garbage();   // removed faces only: the vertices keep their numbers
  return polygons;
}

} // namespace af_tool
