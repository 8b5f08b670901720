// The normals and the curvature written with the faired mesh (see written_normals_and_curvature.h).
#include "written_normals_and_curvature.h"

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>

#include <string>

namespace af_tool {

namespace {

typedef AF::Loop_limit_surface<Mesh> Limit;

void write_curvature(const Limit& limit, Mesh& mesh)
{
  std::vector<Limit::Curvature> values(mesh.number_of_vertices());
  limit.vertex_curvatures(CGAL::make_property_map(values));
  auto k1 = mesh.add_property_map<Vertex_index, double>(curvature_properties[0], 0.0).first;
  auto k2 = mesh.add_property_map<Vertex_index, double>(curvature_properties[1], 0.0).first;
  auto h = mesh.add_property_map<Vertex_index, double>(curvature_properties[2], 0.0).first;
  for(Vertex_index v : mesh.vertices())
  {
    const Limit::Curvature& c = values[std::size_t(v)];
    k1[v] = c.k1;
    k2[v] = c.k2;
    h[v] = 0.5 * (c.k1 + c.k2);
  }
}

// The limit surface of the faired control points serves the curvature and the exact normals.
void write_limit_quantities(const Options& o, bool exact_limit_normals, const std::vector<Point>& control_points,
                            Mesh& mesh, Run_record& r)
{
  // Only the curvature's averages use the quadrature (the run's degree); otherwise degree 4 is the
  // cheapest set-up.
  Mesh control = mesh;
  for(Vertex_index v : control.vertices()) control.point(v) = control_points[std::size_t(v)];
  const Limit limit(control, AF::parameters::quadrature_degree(o.curvature ? o.fairing.quadrature_degree : 4));
  if(o.curvature)
  {
    write_curvature(limit, mesh);
    r.curvature = true;
  }
  if(exact_limit_normals) limit.limit_normals(mesh.property_map<Vertex_index, Vector>("v:normal").first);
}

} // namespace

void check_curvature_properties_free(const Options& o, const Mesh& mesh)
{
  if(!o.curvature) return;
  for(const std::string& p : mesh.properties<Vertex_index>())
    for(const char* c : curvature_properties)
      if(p == c)
        fail("input_error", "--curvature: " + o.input + " already has a vertex property '" + p.substr(2) +
                            "', which it would overwrite");
}

bool writes_exact_limit_normals(const Options& o, const Input_info& info, bool fair_geometry)
{
  const bool limit_written = o.fairing.finite_element == AF::Finite_element::LOOP &&
                             o.fairing.output_positions == AF::Output_positions::LIMIT_SURFACE;
  return info.has_normals && limit_written && fair_geometry;
}

void write_normals_and_curvature(const Options& o, const Input_info& info, bool fair_geometry,
                                 const std::vector<Point>& control_points, Mesh& mesh, Run_record& r)
{
  // a kept normal-field result writes its vertices, which lie on no limit surface: its normals are the mesh's
  const bool exact_limit_normals =
    writes_exact_limit_normals(o, info, fair_geometry) && r.report.selected_tensor != "normal field";
  if(o.curvature || exact_limit_normals) write_limit_quantities(o, exact_limit_normals, control_points, mesh, r);
  if(!info.has_normals) return;
  Normal_map normals = mesh.property_map<Vertex_index, Vector>("v:normal").first;
  if(exact_limit_normals)
    r.normals = "limit_surface";   // written above, with the limit positions
  else if(fair_geometry || !info.normals_read)
  {
    CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
    r.normals = "vertex_normals";
  }
  else
    r.normals = "input";   // the geometry was not faired: the input's normals are still right
}

} // namespace af_tool
