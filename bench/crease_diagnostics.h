// Where bench_denoising's anisotropic tensor can and cannot tell creases from noise, printed for the
// best anisotropic cell of a model: max(|k1|,|k2|) l0 at face centres of the Loop limit surfaces of
// Noisy, (M_eps of Noisy,) Original and the result, split into faces on a crease of Original (an edge
// with dihedral angle > 30 deg), faces next to one (sharing a vertex) and the rest, with the fraction of
// faces whose g(k_max) < 0.5 per lambda, and the mean normal angle error per class.

#ifndef AF_BENCH_CREASE_DIAGNOSTICS_H
#define AF_BENCH_CREASE_DIAGNOSTICS_H

#include <CGAL/Anisotropic_fairing/Loop_limit_surface.h>
#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>
#include <CGAL/boost/graph/helpers.h>

#include "bench_cases.h"
#include "denoising_checks.h"    // run_incremental
#include "denoising_quality.h"
#include "denoising_sweeps.h"    // Best, aniso_lambdas, aniso_tensor
#include "loop_limit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

// Per face of `m` (control mesh), max and min of |k1|, |k2| of its Loop limit surface at the face centre, times l0.
void face_curvatures(const Mesh& m, double l0, std::vector<double>& kmax, std::vector<double>& kmin)
{
  const AF::Loop_limit_surface<Mesh> s(m);
  kmax.clear();
  kmin.clear();
  for(Mesh::Face_index f : m.faces())
  {
    const auto c = s.curvature(f, { { 1.0 / 3, 1.0 / 3, 1.0 / 3 } });
    kmax.push_back(std::max(std::abs(c.k1), std::abs(c.k2)) * l0);
    kmin.push_back(std::min(std::abs(c.k1), std::abs(c.k2)) * l0);
  }
}

double quantile(std::vector<double> v, double q)
{
  if(v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

// The class of each face of `original`: 0 = on a crease (an edge with dihedral angle > 30 deg),
// 1 = sharing a vertex with one, 2 = other.
std::vector<int> crease_classes(const Mesh& original)
{
  std::vector<int> cls(num_faces(original), 2);
  const double cos30 = std::cos(30.0 * pi / 180.0);
  for(Mesh::Face_index f : original.faces())
    for(Mesh::Halfedge_index hh : CGAL::halfedges_around_face(original.halfedge(f), original))
    {
      const Mesh::Face_index g = original.face(original.opposite(hh));
      if(g == Mesh::null_face()) continue;
      const Vector a = face_normal(original, f), b = face_normal(original, g);
      if(a * b < cos30 * std::sqrt(a.squared_length() * b.squared_length())) cls[std::size_t(f)] = 0;
    }
  for(Mesh::Face_index f : original.faces())
    if(cls[std::size_t(f)] == 0)
      for(Mesh::Vertex_index v : CGAL::vertices_around_face(original.halfedge(f), original))
        for(Mesh::Face_index g : CGAL::faces_around_target(original.halfedge(v), original))
          if(g != Mesh::null_face() && cls[std::size_t(g)] == 2) cls[std::size_t(g)] = 1;
  return cls;
}

// The diagnostics of the best anisotropic cell `aniso` (and of the best isotropic Loop cell `loop`, if run).
void aniso_diagnostics(const Mesh& noisy, const Mesh& original, const Reference& ref, double l0, double l2,
                       const Best& aniso, const Best& loop)
{
  const std::vector<int> cls = crease_classes(original);
  const char* names[3] = { "crease", "next to crease", "other" };
  std::size_t count[3] = { 0, 0, 0 };
  for(int c : cls) ++count[c];

  const double tau = aniso.tau_rel * l2;
  const Mesh result = run_incremental(noisy, tau, aniso.steps, aniso_tensor(aniso.lambda_rel / l0, aniso.epsilon_rel * l0 * l0));
  // M_eps of Noisy: one isotropic implicit step of eps (what the prefilter computes at the first step)
  const Mesh noisy_eps = aniso.epsilon_rel > 0 ? run_incremental(noisy, aniso.epsilon_rel * l0 * l0, 1, AF::Isotropic_diffusion_tensor()) : noisy;
  const Mesh iso_same = run_incremental(noisy, tau, aniso.steps, AF::Isotropic_diffusion_tensor());
  std::printf("\ncurvature diagnostics (best anisotropic cell %s; l0 = %.4g): faces of Original: %zu crease, %zu next to crease, %zu other\n",
              aniso.setting.c_str(), l0, count[0], count[1], count[2]);
  std::printf("k = max(|k1|,|k2|) l0, kmin = min(|k1|,|k2|) l0 of the Loop limit surface at face centres; "
              "'g<0.5 @L' = fraction of faces with g(k) < 0.5 (k > 2L) for lambda_rel L\n\n| surface | faces | k p10 | k p50 | k p90 | kmin p50 |");
  for(double L : aniso_lambdas) std::printf(" g<0.5 @%g |", L);
  std::printf("\n|---|---|---|---|---|---|");
  for(std::size_t i = 0; i < aniso_lambdas.size(); ++i) std::printf("---|");
  std::printf("\n");
  struct Named { const char* name; const Mesh* m; };
  std::vector<Named> surfaces = { { "Noisy", &noisy } };
  const std::string eps_name = "M_eps of Noisy (eps_rel " + fmt("%g", aniso.epsilon_rel) + ")";
  if(aniso.epsilon_rel > 0) surfaces.push_back({ eps_name.c_str(), &noisy_eps });
  surfaces.push_back({ "Original", &original });
  surfaces.push_back({ "aniso result", &result });
  for(const Named& sf : surfaces)
  {
    std::vector<double> kmax, kmin;
    face_curvatures(*sf.m, l0, kmax, kmin);
    for(int c = 0; c < 3; ++c)
    {
      std::vector<double> a, b;
      for(std::size_t i = 0; i < cls.size(); ++i)
        if(cls[i] == c) { a.push_back(kmax[i]); b.push_back(kmin[i]); }
      std::printf("| %s, %s | %zu | %.1f | %.1f | %.1f | %.1f |", sf.name, names[c], a.size(), quantile(a, 0.1),
                  quantile(a, 0.5), quantile(a, 0.9), quantile(b, 0.5));
      for(double L : aniso_lambdas)
      {
        std::size_t damped = 0;
        for(double k : a) damped += k > 2 * L ? 1 : 0;
        std::printf(" %.2f |", a.empty() ? 0.0 : double(damped) / double(a.size()));
      }
      std::printf("\n");
    }
  }
  // mean normal angle error per face class
  std::vector<std::pair<std::string, Mesh> > results;
  results.emplace_back("Loop limit of Noisy", limit_mesh(noisy));
  results.emplace_back("isotropic Loop, same tau x steps (" + fmt("%g", aniso.tau_rel) + " x " + std::to_string(aniso.steps) + ")", limit_mesh(iso_same));
  if(loop.run && loop.q.ok())
    results.emplace_back("isotropic Loop best (" + loop.setting + ")",
                         limit_mesh(run_incremental(noisy, loop.tau_rel * l2, loop.steps, AF::Isotropic_diffusion_tensor())));
  results.emplace_back("anisotropic Loop best (" + aniso.setting + ")", limit_mesh(result));
  results.emplace_back("the same, control points (no limit projection)", result);
  results.emplace_back("Loop limit of Original (what a limit-surface output loses at creases)", limit_mesh(original));
  std::printf("\nmean normal angle error (deg) per face class of Original\n\n| result | crease | next to crease | other | all |\n|---|---|---|---|---|\n");
  for(const auto& r : results)
  {
    const std::vector<double> a = face_angles(r.second, ref);
    double sum[3] = { 0, 0, 0 }, all = 0;
    for(std::size_t i = 0; i < a.size(); ++i) { sum[cls[i]] += a[i]; all += a[i]; }
    std::printf("| %s | %.2f | %.2f | %.2f | %.2f |\n", r.first.c_str(), sum[0] / double(std::max<std::size_t>(count[0], 1)),
                sum[1] / double(std::max<std::size_t>(count[1], 1)), sum[2] / double(std::max<std::size_t>(count[2], 1)), all / double(a.size()));
  }
}

#endif // AF_BENCH_CREASE_DIAGNOSTICS_H
