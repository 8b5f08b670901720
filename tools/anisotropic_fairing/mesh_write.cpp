// Writing the meshes of anisotropic_fairing (see mesh_io.h): full double precision, the vertices in their
// order, every vertex property the output format holds, with work-arounds for what CGAL 5.5's writers drop.
#include "mesh_io.h"

#include "captured_streams.h"
#include "element_properties.h"

#include <CGAL/Surface_mesh/IO/OFF.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/STL.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace af_tool {
namespace fs = std::filesystem;

namespace {

// CGAL's PLY writer writes a colour with an alpha. When the input had none (mesh_io.cpp folds a PLY's alpha
// into the colour), the colour goes out as the three uchar properties red, green, blue (prefix "v:" or
// "f:") instead, so that the output's properties are the input's. Returns whether it did.
template <typename Index, typename Range>
bool unfold_rgb(Mesh& mesh, const Range& range, const std::string& prefix)
{
  Mesh::Property_map<Index, CGAL::IO::Color> color;
  bool has_color = false;
  std::tie(color, has_color) = mesh.property_map<Index, CGAL::IO::Color>(prefix + "color");
  if(!has_color) return false;
  auto red = mesh.add_property_map<Index, boost::uint8_t>(prefix + "red", 0).first;
  auto green = mesh.add_property_map<Index, boost::uint8_t>(prefix + "green", 0).first;
  auto blue = mesh.add_property_map<Index, boost::uint8_t>(prefix + "blue", 0).first;
  for(Index i : range)
  {
    red[i] = color[i].red();
    green[i] = color[i].green();
    blue[i] = color[i].blue();
  }
  mesh.remove_property_map(color);
  return true;
}

} // namespace

// ------------------------------------------------------------------------------------------------
// Output
// ------------------------------------------------------------------------------------------------
// The properties of the mesh that a file of format `f` does not hold (warned about, not an error).
std::vector<std::string> dropped_properties(const Mesh& mesh, Format f)
{
  std::vector<std::string> all = mesh.properties<Vertex_index>();
  for(const std::string& p : mesh.properties<Face_index>()) all.push_back(p);
  for(const std::string& p : mesh.properties<Mesh::Edge_index>()) all.push_back(p);
  for(const std::string& p : mesh.properties<Mesh::Halfedge_index>()) all.push_back(p);
  std::vector<std::string> dropped;
  for(const std::string& p : all)
  {
    if(is_internal_property(p)) continue;
    bool kept = false;
    if(f == Format::PLY)  // CGAL's Surface_mesh PLY writer writes normals, colours and every numeric property
      kept = p == "v:normal" || p == "v:color" || p == "f:color" ||
             (p.compare(0, 2, "v:") == 0 && is_numeric_property<Vertex_index>(mesh, p)) ||
             (p.compare(0, 2, "f:") == 0 && is_numeric_property<Face_index>(mesh, p)) ||
             (p.compare(0, 2, "e:") == 0 && is_numeric_property<Mesh::Edge_index>(mesh, p)) ||
             (p.compare(0, 2, "h:") == 0 && is_numeric_property<Mesh::Halfedge_index>(mesh, p));
    else if(f == Format::OFF) kept = (p == "v:normal" || p == "v:color" || p == "v:texcoord" || p == "f:color");
    else if(f == Format::OBJ) kept = (p == "v:normal" || p == "v:texcoord");
    if(!kept) dropped.push_back(p);
  }
  return dropped;
}

namespace {

// OBJ with normals or texture coordinates, which CGAL's OBJ writer does not attach to the vertices
// (it writes vn lines but faces without //n references, and no vt). This writes one vn and one vt per
// vertex, in the vertex order, and faces "f a//a", "f a/a" or "f a/a/a".
bool write_obj_with_vertex_data(std::ostream& os, const Mesh& mesh, const Normal_map* normals, const Texcoord_map* uv)
{
  os.precision(17);
  os << "# written by anisotropic_fairing\n";
  os << "# " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces\n";
  for(Vertex_index v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    os << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  if(uv)
    for(Vertex_index v : mesh.vertices())
    {
      const Texcoord& t = (*uv)[v];
      os << "vt " << t.x() << ' ' << t.y() << '\n';
    }
  if(normals)
    for(Vertex_index v : mesh.vertices())
    {
      const Vector& n = (*normals)[v];
      os << "vn " << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
    }
  for(Face_index f : mesh.faces())
  {
    os << 'f';
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      const std::size_t i = std::size_t(v) + 1;
      os << ' ' << i;
      if(uv) os << '/' << i;
      if(normals) os << (uv ? "/" : "//") << i;
    }
    os << '\n';
  }
  return bool(os);
}

} // namespace

void write_mesh(const std::string& path, Format f, const Mesh& mesh, const Input_info& info, bool with_normals,
                bool text)
{
  bool ok = false;
  errno = 0;   // the failing open, write or close says why (system_reason)
  {
    Capture_streams capture;
    if(f == Format::STL)
    {
      // triangles only; binary STL holds single-precision floats, text STL the full doubles
      std::ofstream out(path, std::ios::binary);
      if(out)
      {
        CGAL::IO::set_mode(out, text ? CGAL::IO::ASCII : CGAL::IO::BINARY);
        ok = CGAL::IO::write_STL(out, mesh, CGAL::parameters::stream_precision(17));
        out.close();
        ok = ok && !out.fail();
      }
    }
    else if(f == Format::PLY)
    {
      const bool binary = !text && info.format == Format::PLY && info.ply_binary;
      std::ofstream out(path, std::ios::binary);
      if(out)
      {
        CGAL::IO::set_mode(out, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
        // colours without the alpha the input did not have (a copy: the mesh is the caller's)
        const bool vertex_rgb =
          !info.vertex_alpha && mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color").second;
        const bool face_rgb = !info.face_alpha && mesh.property_map<Face_index, CGAL::IO::Color>("f:color").second;
        if(vertex_rgb || face_rgb)
        {
          Mesh rgb = mesh;
          if(vertex_rgb) unfold_rgb<Vertex_index>(rgb, rgb.vertices(), "v:");
          if(face_rgb) unfold_rgb<Face_index>(rgb, rgb.faces(), "f:");
          ok = CGAL::IO::write_PLY(out, rgb, info.ply_comments, CGAL::parameters::stream_precision(17));
        }
        else ok = CGAL::IO::write_PLY(out, mesh, info.ply_comments, CGAL::parameters::stream_precision(17));
        out.close();
        ok = ok && !out.fail();
      }
    }
    else if(f == Format::OFF)
    {
      std::ofstream out(path);
      if(out)
      {
        // the Surface_mesh overload also writes v:normal, v:color, v:texcoord and f:color
        ok = CGAL::IO::write_OFF(out, mesh, CGAL::parameters::stream_precision(17));
        out.close();
        ok = ok && !out.fail();
      }
    }
    else
    {
      std::ofstream out(path);
      if(out)
      {
        const auto normals = mesh.property_map<Vertex_index, Vector>("v:normal");
        const auto uv = mesh.property_map<Vertex_index, Texcoord>("v:texcoord");
        if((with_normals && normals.second) || uv.second)
          ok = write_obj_with_vertex_data(out, mesh, with_normals && normals.second ? &normals.first : nullptr,
                                          uv.second ? &uv.first : nullptr);
        else
          ok = CGAL::IO::write_OBJ(out, mesh, CGAL::parameters::stream_precision(17));
        out.close();
        ok = ok && !out.fail();
      }
    }
  }
  if(!ok) fail("write_error", "cannot write " + path + system_reason(errno));
}

fs::path temporary_next_to(const std::string& path)
{
  const fs::path p(path);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  // the extension kept last, so that a reader (--snapshot's renderer) knows the format
  return dir / ("." + p.stem().string() + ".tmp" + std::to_string(long(::getpid())) + p.extension().string());
}

void fail_writing(const Failure& f, const fs::path& written, const std::string& shown)
{
  std::error_code ec;
  fs::remove(written, ec);
  std::string message = f.message;
  const std::size_t at = message.find(written.string());
  if(at == std::string::npos) fail("write_error", "cannot write " + shown);
  message.replace(at, written.string().size(), shown);
  fail("write_error", message);
}

std::string write_file_atomically(const std::string& path, const std::string& text)
{
  const fs::path tmp = temporary_next_to(path);
  errno = 0;
  {
    std::ofstream out(tmp, std::ios::binary);
    if(!out) return std::strerror(errno ? errno : EIO);
    out << text;
    out.close();
    if(out.fail())
    {
      const int err = errno ? errno : EIO;
      std::error_code ec;
      fs::remove(tmp, ec);
      return std::strerror(err);
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if(ec) { std::error_code ec2; fs::remove(tmp, ec2); return ec.message(); }
  return std::string();
}

} // namespace af_tool
