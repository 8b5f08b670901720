// The noisy cases, the measures and the arguments shared by the denoising benchmarks (bench_denoising uses
// the measures and the pair reading; bench_defaults and bench_peers all of it).
//
// Cases (noisy mesh + noise-free original of identical connectivity):
//   - every <DATA_DIR>/denoising/<Name>/{Noisy,Original}.obj (the scans have borders);
//   - generated from clean models: Gaussian noise of sigma = 0.2 h and 0.5 h along the area-weighted vertex
//     normals of the original (h = its mean edge length; std::mt19937, the seed is printed), and
//     quantisation of the coordinates to a number of bits per axis of the bounding box.
// Case names: the pair directories (Fandisk0.3, ...), "<model> gauss0.2", "<model> gauss0.5", "<model> quant<bits>".

#ifndef AF_BENCH_CASES_H
#define AF_BENCH_CASES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include "bench_mesh_measures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;

static const double pi = 3.14159265358979323846;
static const double nan_value = std::numeric_limits<double>::quiet_NaN();

std::string fmt(const char* f, double x)
{
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

// Keeps the file's vertex and face order, so that Noisy and Original correspond by index.
bool read_obj_in_order(const std::string& path, Mesh& mesh)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_OBJ(path, points, polygons) || !PMP::is_polygon_soup_a_polygon_mesh(polygons)) return false;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  return num_vertices(mesh) == points.size() && num_faces(mesh) == polygons.size();
}

Vector face_normal(const Mesh& m, Mesh::Face_index f)   // length = 2 area
{
  const Mesh::Halfedge_index h = m.halfedge(f);
  const Point& a = m.point(m.source(h));
  return CGAL::cross_product(m.point(m.target(h)) - a, m.point(m.target(m.next(h))) - a);
}

std::vector<Vector> face_normals(const Mesh& m)
{
  std::vector<Vector> n;
  n.reserve(num_faces(m));
  for(Mesh::Face_index f : m.faces()) n.push_back(face_normal(m, f));
  return n;
}

// Area-weighted unit vertex normals (CGAL 5.5's compute_vertex_normals weighs by visibility, not area).
std::vector<Vector> area_weighted_normals(const Mesh& m)
{
  std::vector<Vector> n(num_vertices(m), CGAL::NULL_VECTOR);
  for(Mesh::Face_index f : m.faces())
  {
    const Vector fn = face_normal(m, f);
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) n[v.idx()] = n[v.idx()] + fn;
  }
  for(Vector& v : n)
    if(v.squared_length() > 0) v = v / std::sqrt(v.squared_length());
  return n;
}

// The angle (radians) between two vectors of any length.
double normal_angle(const Vector& n, const Vector& r)
{
  return std::atan2(std::sqrt(CGAL::cross_product(n, r).squared_length()), n * r);
}

bool finite_points(const Mesh& m)
{
  for(Mesh::Vertex_index v : m.vertices())
  {
    const Point& p = m.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return false;
  }
  return true;
}

// Mean angle (degrees) between corresponding face normals; NaN if a position is not finite.
double normal_error(const Mesh& m, const std::vector<Vector>& reference)
{
  if(!finite_points(m)) return nan_value;
  double sum = 0;
  std::size_t i = 0;
  for(Mesh::Face_index f : m.faces()) sum += normal_angle(face_normal(m, f), reference[i++]);
  return sum / double(num_faces(m)) * 180.0 / pi;
}

// Interior edges whose two faces' normals make an angle > 120 degrees (cos < -1/2): folds.
std::size_t folded_edges(const Mesh& m)
{
  std::size_t count = 0;
  for(Mesh::Edge_index e : m.edges())
  {
    const Mesh::Halfedge_index h = m.halfedge(e);
    if(m.is_border(h) || m.is_border(m.opposite(h))) continue;
    const Vector a = face_normal(m, m.face(h)), b = face_normal(m, m.face(m.opposite(h)));
    if(a * b < -0.5 * std::sqrt(a.squared_length() * b.squared_length())) ++count;
  }
  return count;
}

double bbox_diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = PMP::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

struct Case
{
  std::string name;
  std::function<bool(Case&)> load;   // fills the meshes; false: unreadable or unsuitable
  Mesh noisy, original;
  std::string note;
  double nominal_sigma = nan_value;  // generated cases: the sigma asked for, in units of h
};

// Reads a clean model, triangulated if needed; `closed` refuses a mesh with borders.
bool read_clean(const std::string& path, Mesh& m, std::string& note, bool closed = false)
{
  if(!CGAL::IO::read_polygon_mesh(path, m) || num_faces(m) == 0) { note = "cannot read " + path; return false; }
  if(!CGAL::is_triangle_mesh(m))
  {
    if(closed) { note = "not a triangle mesh"; return false; }
    PMP::triangulate_faces(m);
    note = "triangulated; ";
  }
  if(closed && !CGAL::is_closed(m)) { note = "has borders"; return false; }
  return true;
}

void add_gaussian(Case& c, double relative_sigma, unsigned seed)
{
  const std::vector<Vector> n = area_weighted_normals(c.original);
  const double sigma = relative_sigma * mean_edge_length(c.original);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  c.noisy = c.original;
  for(Mesh::Vertex_index v : c.noisy.vertices()) c.noisy.point(v) = c.noisy.point(v) + gauss(rng) * n[v.idx()];
  c.nominal_sigma = relative_sigma;
  c.note += "Gaussian sigma " + std::to_string(relative_sigma).substr(0, 3) + " h along the normals, seed " + std::to_string(seed);
}

void add_quantisation(Case& c, int bits)
{
  const double levels = std::ldexp(1.0, bits) - 1;
  const CGAL::Bbox_3 b = PMP::bbox(c.original);
  double step[3], sum2 = 0;
  for(int a = 0; a < 3; ++a) { step[a] = (b.max(a) - b.min(a)) / levels; sum2 += step[a] * step[a]; }
  c.noisy = c.original;
  for(Mesh::Vertex_index v : c.noisy.vertices())
  {
    const Point& p = c.noisy.point(v);
    double q[3];
    for(int a = 0; a < 3; ++a) q[a] = step[a] > 0 ? b.min(a) + std::round((p[a] - b.min(a)) / step[a]) * step[a] : p[a];
    c.noisy.point(v) = Point(q[0], q[1], q[2]);
  }
  // uniform rounding error: variance step^2/12 per axis (mean over the axes, for a random normal)
  c.nominal_sigma = std::sqrt(sum2 / 3 / 12) / mean_edge_length(c.original);
  c.note += std::to_string(bits) + "-bit quantisation, steps " + fmt("%.3g", step[0]) + ", " + fmt("%.3g", step[1]) + ", " + fmt("%.3g", step[2]);
}

// RMS of the displacement noisy - original along the original's normals, in units of its h.
double measured_sigma(const Case& c)
{
  const std::vector<Vector> n = area_weighted_normals(c.original);
  double sum = 0;
  for(Mesh::Vertex_index v : c.original.vertices()) sum += CGAL::square((c.noisy.point(v) - c.original.point(v)) * n[v.idx()]);
  return std::sqrt(sum / double(num_vertices(c.original))) / mean_edge_length(c.original);
}

// Mean distance of the vertices of a result to the noise-free surface (drift and shrinkage), in units
// of the original's mean edge length.
class Distance_to_original
{
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
  Tree tree_;
  double h_;

public:
  explicit Distance_to_original(const Mesh& original) : tree_(faces(original).first, faces(original).second, original),
                                                         h_(mean_edge_length(original))
  {
    tree_.accelerate_distance_queries();
  }
  double operator()(const Mesh& m) const
  {
    if(num_vertices(m) == 0) return nan_value;
    double sum = 0;
    for(Mesh::Vertex_index v : m.vertices()) sum += std::sqrt(tree_.squared_distance(m.point(v)));
    return sum / double(num_vertices(m)) / h_;
  }
};

#ifndef AF_SOURCE_DIR   // set by CMake: the source directory the project was configured with
#define AF_SOURCE_DIR "."
#endif

// The arguments of the programs on these cases (bench_defaults, bench_peers):
// [DATA_DIR=<repo>/../shared/data] [CASE_SUBSTRING] [PARTS], PARTS a string of part letters.
struct Case_arguments
{
  std::string dir, only, parts;
  bool part(char p) const { return parts.find(p) != std::string::npos; }
};

// False (and a message on stderr) if PARTS has a letter not in `letters`.
bool read_case_arguments(int argc, char** argv, const std::string& default_parts, const std::string& letters, Case_arguments& a)
{
  a.dir = argc > 1 && argv[1][0] ? argv[1] : std::string(AF_SOURCE_DIR) + "/../shared/data";
  a.only = argc > 2 ? argv[2] : "";
  a.parts = argc > 3 && argv[3][0] ? argv[3] : default_parts;
  if(a.parts.find_first_not_of(letters) == std::string::npos) return true;
  std::string list;
  for(char c : letters) list += (list.empty() ? "" : ", ") + std::string(1, c);
  std::fprintf(stderr, "PARTS: letters of %s\n", list.c_str());
  return false;
}

// The folders of <cases_dir> (write_cases' output) whose names contain `only`, sorted.
std::vector<std::string> case_folders(const std::string& cases_dir, const std::string& only)
{
  std::vector<std::string> cases;
  for(const auto& entry : std::filesystem::directory_iterator(cases_dir))
    if(entry.is_directory() && entry.path().filename().string().find(only) != std::string::npos)
      cases.push_back(entry.path().filename().string());
  std::sort(cases.begin(), cases.end());
  return cases;
}

// The names of the denoising pairs <pairs_dir>/<Name>/{Noisy,Original}.obj, sorted; none if the directory is missing.
std::vector<std::string> denoising_pairs(const std::string& pairs_dir)
{
  std::vector<std::string> pairs;
  if(std::filesystem::is_directory(pairs_dir))
    for(const auto& entry : std::filesystem::directory_iterator(pairs_dir))
      if(std::filesystem::exists(entry.path() / "Noisy.obj") && std::filesystem::exists(entry.path() / "Original.obj"))
        pairs.push_back(entry.path().filename().string());
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// Reads <base>/Noisy.obj and <base>/Original.obj in file order; false (and why in `note`) if they cannot be
// read or differ in size.
bool read_denoising_pair(const std::string& base, Mesh& noisy, Mesh& original, std::string& note)
{
  if(!read_obj_in_order(base + "/Noisy.obj", noisy) || !read_obj_in_order(base + "/Original.obj", original))
  { note = "cannot read " + base; return false; }
  if(num_vertices(noisy) != num_vertices(original) || num_faces(noisy) != num_faces(original))
  { note = "Noisy and Original differ in size"; return false; }
  return true;
}

// The denoising pairs of <dir>/denoising, then, per model of <dir>, Gaussian noise of 0.2 h and 0.5 h
// (the seed depends on the model's place and sigma only) and quantisation to each of `bits`.
std::vector<Case> noisy_cases(const std::string& dir, const std::vector<int>& bits)
{
  std::vector<Case> cases;
  const std::vector<std::string> pairs = denoising_pairs(dir + "/denoising");
  for(const std::string& p : pairs)
    cases.push_back({p, [dir, p](Case& c) { return read_denoising_pair(dir + "/denoising/" + p, c.noisy, c.original, c.note); }});
  const unsigned seed_base = 20261121u;
  const std::vector<std::string> models = {"bunny-closed.off", "camelhead.off", "face.obj", "rocker-arm.obj", "fandisk.off"};
  for(std::size_t i = 0; i < models.size(); ++i)
  {
    const std::string file = models[i], stem = file.substr(0, file.rfind('.'));
    const bool closed = stem == "fandisk";   // taken only if it is a closed triangle mesh
    for(const double sigma : { 0.2, 0.5 })
    {
      const unsigned seed = seed_base + unsigned(pairs.size() + 3 * i + (sigma > 0.3 ? 1 : 0));
      cases.push_back({stem + " gauss" + std::to_string(sigma).substr(0, 3), [dir, file, closed, sigma, seed](Case& c) {
                         if(!read_clean(dir + "/" + file, c.original, c.note, closed)) return false;
                         add_gaussian(c, sigma, seed);
                         return true;
                       }});
    }
    for(const int b : bits)
      cases.push_back({stem + " quant" + std::to_string(b), [dir, file, closed, b](Case& c) {
                         if(!read_clean(dir + "/" + file, c.original, c.note, closed)) return false;
                         add_quantisation(c, b);
                         return true;
                       }});
  }
  return cases;
}

// Models and noise that no default was measured on while it was chosen, a check that what was chosen
// carries over: per model of <dir>, Gaussian noise of 0.3 h along the normals and the same in every
// direction (tangential too, as a scanner's error is), with seeds of their own.
std::vector<Case> held_out_cases(const std::string& dir)
{
  std::vector<Case> cases;
  const std::vector<std::string> models = {"elephant.obj", "lion.off", "fertility.off", "spot.obj", "decimated-max.obj", "bunny.off"};
  for(std::size_t i = 0; i < models.size(); ++i)
  {
    const std::string file = models[i], stem = file.substr(0, file.rfind('.'));
    cases.push_back({"other " + stem + " gauss0.3", [dir, file, i](Case& c) {
                       if(!read_clean(dir + "/" + file, c.original, c.note)) return false;
                       add_gaussian(c, 0.3, 777u + unsigned(i));
                       return true;
                     }});
    cases.push_back({"other " + stem + " every-direction0.3", [dir, file, i](Case& c) {
                       if(!read_clean(dir + "/" + file, c.original, c.note)) return false;
                       const double sigma = 0.3 * mean_edge_length(c.original);
                       std::mt19937 rng(999u + unsigned(i));
                       std::normal_distribution<double> gauss(0.0, sigma);
                       c.noisy = c.original;
                       for(Mesh::Vertex_index v : c.noisy.vertices())
                       {
                         const double x = gauss(rng), y = gauss(rng), z = gauss(rng);
                         c.noisy.point(v) = c.noisy.point(v) + Vector(x, y, z);
                       }
                       c.note += "Gaussian sigma 0.3 h in every direction, seed " + std::to_string(999u + unsigned(i));
                       return true;
                     }});
  }
  return cases;
}

// The noise kinds users meet, for the comparison with the strongest peers (bench/gmnf): per model of
// <dir> (CAD parts, an organic closed model, scans with borders), Gaussian noise of 0.3 h along the
// normals and in random directions, impulsive noise (a tenth of the vertices moved by 1 h along the
// normal, either way), quantisation to 8 and 10 bits, and a range scanner's depth noise: along one
// viewing direction, of deviation 0.2 h / max(|n . d|, 0.25), so that it grows where the surface is
// seen at a grazing angle, and correlated noise as scanners make (Gaussian along the normals averaged once
// with its ring's mean, 0.3 h RMS). Seeds depend on the model's place and the kind only.
std::vector<Case> peer_cases(const std::string& dir)
{
  std::vector<Case> cases;
  const std::vector<std::string> models = {"fandisk.off", "rocker-arm.obj", "bunny-closed.off", "camelhead.off", "face.obj"};
  for(std::size_t i = 0; i < models.size(); ++i)
  {
    const std::string file = models[i], stem = file.substr(0, file.rfind('.'));
    const unsigned seed = 4100u + 16u * unsigned(i);
    const auto kind = [&](const std::string& name, std::function<void(Case&)> add) {
      cases.push_back({stem + " " + name, [dir, file, add](Case& c) {
                         if(!read_clean(dir + "/" + file, c.original, c.note)) return false;
                         add(c);
                         return true;
                       }});
    };
    kind("gauss0.3", [seed](Case& c) { add_gaussian(c, 0.3, seed); });
    kind("random-direction0.3", [seed](Case& c) {
      const double sigma = 0.3 * mean_edge_length(c.original);
      std::mt19937 rng(seed + 1);
      std::normal_distribution<double> gauss(0.0, sigma);
      c.noisy = c.original;
      for(Mesh::Vertex_index v : c.noisy.vertices())
      {
        const double x = gauss(rng), y = gauss(rng), z = gauss(rng);
        c.noisy.point(v) = c.noisy.point(v) + Vector(x, y, z);
      }
      c.note += "Gaussian sigma 0.3 h in random directions";
    });
    kind("impulsive", [seed](Case& c) {
      const std::vector<Vector> n = area_weighted_normals(c.original);
      const double h = mean_edge_length(c.original);
      std::mt19937 rng(seed + 2);
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      c.noisy = c.original;
      for(Mesh::Vertex_index v : c.noisy.vertices())
        if(unit(rng) < 0.1) c.noisy.point(v) = c.noisy.point(v) + (unit(rng) < 0.5 ? -h : h) * n[v.idx()];
      c.note += "impulsive: a tenth of the vertices moved by 1 h along the normal";
    });
    kind("quant8", [](Case& c) { add_quantisation(c, 8); });
    kind("quant10", [](Case& c) { add_quantisation(c, 10); });
    kind("scan-depth", [seed](Case& c) {
      const std::vector<Vector> n = area_weighted_normals(c.original);
      const double h = mean_edge_length(c.original);
      const Vector d(0.36, 0.48, 0.8);   // unit viewing direction
      std::mt19937 rng(seed + 3);
      std::normal_distribution<double> gauss(0.0, 1.0);
      c.noisy = c.original;
      for(Mesh::Vertex_index v : c.noisy.vertices())
      {
        const double facing = std::abs(n[v.idx()] * d);
        c.noisy.point(v) = c.noisy.point(v) + gauss(rng) * 0.2 * h / std::max(facing, 0.25) * d;
      }
      c.note += "depth noise along one viewing direction, 0.2 h / max(|n.d|, 0.25)";
    });
    kind("correlated0.3", [seed](Case& c) {
      const std::vector<Vector> n = area_weighted_normals(c.original);
      const double h = mean_edge_length(c.original);
      std::mt19937 rng(seed + 4);
      std::normal_distribution<double> gauss(0.0, 1.0);
      std::vector<double> u(c.original.number_of_vertices()), w(u.size(), 0.0);
      for(double& x : u) x = gauss(rng);
      double square = 0;
      for(Mesh::Vertex_index v : c.original.vertices())
      {
        double ring = 0, count = 0;
        for(Mesh::Vertex_index j : CGAL::vertices_around_target(c.original.halfedge(v), c.original))
        {
          ring += u[j.idx()];
          count += 1;
        }
        w[v.idx()] = 0.5 * u[v.idx()] + (count > 0 ? 0.5 * ring / count : 0.5 * u[v.idx()]);
        square += w[v.idx()] * w[v.idx()];
      }
      const double scale = 0.3 * h / std::sqrt(square / double(w.size()));
      c.noisy = c.original;
      for(Mesh::Vertex_index v : c.noisy.vertices())
        c.noisy.point(v) = c.noisy.point(v) + scale * w[v.idx()] * n[v.idx()];
      c.note += "correlated noise along the normals, 0.3 h RMS: Gaussian averaged once with its ring's mean (half each)";
    });
  }
  return cases;
}

#endif // AF_BENCH_CASES_H
