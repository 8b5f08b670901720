// anisotropic_fairing tool: what CGAL's OBJ reader leaves out of an OBJ file (obj_vertex_data.h).
#include "obj_vertex_data.h"
#include "message_text.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace af_tool {

namespace {

// the first problem found is the one said
void set_problem(Obj_texcoords& t, const std::string& p)
{
  if(t.problem.empty()) t.problem = p;
}

// an OBJ index (1-based, or negative: relative to the `count` elements read so far) -> 0-based, -1 if invalid
long obj_index(const std::string& text, std::size_t count)
{
  errno = 0;
  char* end = nullptr;
  const long i = std::strtol(text.c_str(), &end, 10);
  if(text.empty() || *end != '\0' || errno == ERANGE || i == 0) return -1;
  const long r = i > 0 ? i - 1 : long(count) + i;
  return r >= 0 && r < long(count) ? r : -1;
}

// the rest of a vt line: up to three numbers, the third dropped
void read_vt(std::istringstream& ls, std::size_t line_number, Obj_texcoords& t, std::vector<std::array<double, 2>>& vt)
{
  t.present = true;
  double c[3] = {0, 0, 0};
  int k = 0;
  std::string token;
  while(k < 3 && ls >> token)
  {
    char* end = nullptr;
    c[k] = std::strtod(token.c_str(), &end);
    if(*end != '\0' || !std::isfinite(c[k]))
    {
      set_problem(t, "line " + std::to_string(line_number) + ": malformed vt");
      break;
    }
    ++k;
  }
  if(k == 0) set_problem(t, "line " + std::to_string(line_number) + ": malformed vt");
  if(c[2] != 0) t.dropped_w = true;
  vt.push_back({{c[0], c[1]}});
}

// the corners of an f line: each vertex's vt (`vt_of`, -1 none yet), one per vertex or a seam
void read_f(std::istringstream& ls, std::size_t line_number, std::size_t nv,
            const std::vector<std::array<double, 2>>& vt, std::vector<long>& vt_of, bool& corner_without_vt,
            Obj_texcoords& t)
{
  std::string token;
  while(ls >> token)
  {
    const std::string::size_type s1 = token.find('/');
    const long v = obj_index(token.substr(0, s1), nv);
    if(v < 0)
    {
      set_problem(t, "line " + std::to_string(line_number) + ": bad vertex index " + quoted_excerpt(token));
      continue;
    }
    std::string tex;
    if(s1 != std::string::npos)
    {
      const std::string::size_type s2 = token.find('/', s1 + 1);
      tex = token.substr(s1 + 1, s2 == std::string::npos ? std::string::npos : s2 - s1 - 1);
    }
    if(tex.empty()) { corner_without_vt = true; continue; }
    const long ti = obj_index(tex, vt.size());
    if(ti < 0)
    {
      set_problem(t, "line " + std::to_string(line_number) + ": bad texture index " + quoted_excerpt(token));
      continue;
    }
    long& used = vt_of[std::size_t(v)];
    if(used < 0) used = ti;
    else if(used != ti && vt[std::size_t(used)] != vt[std::size_t(ti)])
      set_problem(t, "vertex " + std::to_string(v) + " (OBJ index " + std::to_string(v + 1) +
                  ") has two texture coordinates, vt " + std::to_string(used + 1) + " and " +
                  std::to_string(ti + 1) + ": a texture seam");
  }
}

} // namespace

Obj_texcoords read_obj_texcoords(const std::string& path, std::size_t mesh_vertices)
{
  Obj_texcoords t;
  std::ifstream in(path);
  std::vector<std::array<double, 2>> vt;
  std::vector<long> vt_of;   // per vertex: the vt index it uses, -1 none yet
  std::size_t nv = 0, line_number = 0;
  bool corner_without_vt = false;
  std::string line, token;
  while(std::getline(in, line))
  {
    ++line_number;
    std::istringstream ls(line);
    if(!(ls >> token)) continue;
    if(token == "v") { ++nv; vt_of.push_back(-1); }
    else if(token == "vt") read_vt(ls, line_number, t, vt);
    else if(token == "f") read_f(ls, line_number, nv, vt, vt_of, corner_without_vt, t);
  }
  if(!t.present) return t;
  if(corner_without_vt) set_problem(t, "some face corners have no texture coordinate");
  if(nv != mesh_vertices)
    set_problem(t, "the file has " + std::to_string(nv) + " v lines but the mesh " + std::to_string(mesh_vertices) +
                " vertices");
  if(!t.problem.empty()) return t;
  t.uv.resize(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(vt_of[i] >= 0) t.uv[i] = vt[std::size_t(vt_of[i])];
    else if(vt.size() == nv) t.uv[i] = vt[i];   // a vertex on no face: its own vt if there is one per v
    else t.uv[i] = {{0, 0}};                    // otherwise (a vertex on no face, never referenced) 0 0
  }
  t.matched = true;
  return t;
}

void scan_obj(const std::string& path, bool& normals, bool& textures, bool& colors)
{
  normals = textures = colors = false;
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
  {
    if(line.compare(0, 3, "vn ") == 0 || line.compare(0, 3, "vn\t") == 0) normals = true;
    else if(line.compare(0, 3, "vt ") == 0 || line.compare(0, 3, "vt\t") == 0) textures = true;
    else if(!colors && (line.compare(0, 2, "v ") == 0 || line.compare(0, 2, "v\t") == 0))
    {
      std::istringstream ls(line.substr(2));
      double x;
      int n = 0;
      while(ls >> x) ++n;
      if(n >= 6) colors = true;
    }
  }
}

} // namespace af_tool
