// The noise model read from a mesh alone (internal/flow/Noise_model.h) against the noise put on it.
//
// A unit icosphere of 10242 vertices (smooth, nearly regular: its own reading is close to nothing) under noise of
// known law, h its mean edge length:
// - 0.2 h along the normals: read 0.2 h along (10%), little across (below 0.35 of it: what the normal noise leaks
//   into the in-plane offsets); the same in every direction: 0.2 h both ways (10%, 15%);
// - 0.05 h on the upper half, 0.15 h on the lower (where the differences are still linear in the noise: at 0.3 h
//   the ring planes and spacings follow it, and 0.3 h reads as 0.25 h): the scales' means on the caps |z| > 0.3 in
//   a ratio of 3 (2.4 to 3.6), where homoscedastic noise reads a spread (90th over 10th percentile) below 1.3;
// - 0.1 h plus 2% of the vertices thrown 1.5 h off along the normal: a hit share of 1.5 to 2.5%, probability above
//   one half on at least 90% of the vertices thrown and on at most 0.5% of the others; none without impulses;
//   a tenth of the vertices thrown 1 h: over 5% read, at least half of them found, at most 1% of the others;
// - the fandisk, a tenth of its vertices thrown 1 h along the normals: over 5% read, at least half of them
//   found, others at most a fifth of those found;
// - Gaussian noise along the normals averaged once with its ring's mean, 0.2 h RMS: read below 0.8 of it by the
//   second differences, within 15% with its correlation (k from 0.7 to 1.3); independent noise and the clean sphere
//   left as read; SURE of a linear smoother under that noise, probed with noise as correlated as the noise read,
//   unbiased over eight draws (within 0.03 per vertex), biased probed with independent noise (below -0.2);
// - the coordinates rounded to a lattice of 0.25 h: its step found to 1e-9; none without rounding, none for a
//   lattice coarser than the edges;
// - the same noisy sphere with its vertices and faces numbered in another order: the same estimate (to 1e-12), the
//   same probe at each vertex (to the bit) and the same reference noise (to rounding: 1e-12), with the numbers drawn by the vertices' keys
//   (Vertex_keys.h), as a process of the distributed program draws those of its part alone; drawn by the vertices'
//   numbers, they differ;
// - on a mesh with a border (the hemisphere), the probe made as correlated as a reading of k = 1.5: at every vertex
//   the mean of two and of one averagings with the ring, the ghosts of the border's fans included (drawn by their
//   keys), against the same averaging made here from the faces around each vertex; before, the rings of border
//   vertices read past the end of the probe's values.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Anisotropic_fairing/internal/flow/Noise_model.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Indexed_mesh.h>
#include <CGAL/Anisotropic_fairing/internal/mesh/Vertex_keys.h>
#include <CGAL/Anisotropic_fairing/internal/run/Tensor_selection.h>

#include "test_support/check.h"
#include "test_support/mesh_generators.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

struct Sphere
{
  Mesh mesh;
  AFI::Control_matrix x;
  double h = 0;
  std::unique_ptr<AFI::Indexed_mesh<Mesh>> im;

  Sphere()
  {
    AF_test::soup_to_mesh(AF_test::icosphere_soup(5), mesh);
    im.reset(new AFI::Indexed_mesh<Mesh>(mesh, AFI::Borders::GHOSTED, true));
    x = im->read_points(get(CGAL::vertex_point, mesh));
    double sum = 0;
    std::size_t count = 0;
    for(Mesh::Edge_index e : mesh.edges())
    {
      sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(mesh.halfedge(e))),
                                              mesh.point(mesh.target(mesh.halfedge(e)))));
      ++count;
    }
    h = sum / double(count);
  }

  AFI::Noise_model model(const AFI::Control_matrix& y) const
  {
    const AFI::Ghost_layer& layer = im->ghost_layer();
    const std::vector<bool> usable(std::size_t(y.rows()), true);
    const AFI::Noise_estimate noise(*layer.topology, y, usable);
    return AFI::estimate_noise_model(*layer.topology, y, usable, noise, h);
  }
};

// x moved by sigma(i) (in h) along the radius and, with `across`, the same in both directions across it
template <typename Sigma>
AFI::Control_matrix noisy(const Sphere& s, Sigma sigma, bool across, unsigned seed)
{
  AFI::Control_matrix y = s.x;
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for(Eigen::Index i = 0; i < y.rows(); ++i)
  {
    const Eigen::RowVector3d n = s.x.row(i).head<3>().normalized();
    Eigen::RowVector3d e = gauss(rng) * n;
    if(across)
    {
      const Eigen::RowVector3d g(gauss(rng), gauss(rng), gauss(rng));
      e += g - g.dot(n) * n;
    }
    y.row(i).head<3>() += sigma(i) * s.h * e;
  }
  return y;
}

void along_and_across(const Sphere& s)
{
  const auto constant = [](Eigen::Index) { return 0.2; };
  const AFI::Noise_model along = s.model(noisy(s, constant, false, 1));
  const AFI::Noise_model both = s.model(noisy(s, constant, true, 2));
  std::printf("along the normals: %s\nin every direction: %s\n", along.description().c_str(),
              both.description().c_str());
  AF_CHECK(std::abs(along.normal / 0.2 - 1) < 0.1, "noise along the normals is read along them");
  AF_CHECK(along.tangential < 0.35 * along.normal, "noise along the normals reads little across them");
  AF_CHECK(std::abs(both.normal / 0.2 - 1) < 0.1, "isotropic noise is read along the normals");
  AF_CHECK(std::abs(both.tangential / 0.2 - 1) < 0.15, "isotropic noise is read across the normals");
  AF_CHECK(along.normal_spread < 1.3 && both.tangential_spread < 1.3, "homoscedastic noise reads no spread");
  AF_CHECK(along.hit_share < 0.002, "Gaussian noise reads no impulses");
  AF_CHECK(along.cell[0] == 0 && along.cell[1] == 0 && along.cell[2] == 0, "unrounded coordinates: no lattice");
}

void over_the_surface(const Sphere& s)
{
  const AFI::Noise_model m = s.model(noisy(s, [&](Eigen::Index i) { return s.x(i, 2) > 0 ? 0.05 : 0.15; }, false, 3));
  double lower = 0, upper = 0, nl = 0, nu = 0;
  for(Eigen::Index i = 0; i < s.x.rows(); ++i)
  {
    if(s.x(i, 2) < -0.3) { lower += m.normal_scale[std::size_t(i)]; nl += 1; }
    if(s.x(i, 2) > 0.3) { upper += m.normal_scale[std::size_t(i)]; nu += 1; }
  }
  const double ratio = (lower / nl) / (upper / nu);
  std::printf("0.05 h above, 0.15 h below: %s; the caps' scales in a ratio of %.3f\n", m.description().c_str(), ratio);
  AF_CHECK(ratio > 2.4 && ratio < 3.6, "the deviation's variation over the surface is read");
}

// `share` of the vertices thrown `size` h off along the normal over 0.1 h of Gaussian noise: the hits found, and
// the others taken for hits.
void impulses(const Sphere& s, double base, double share, double size, unsigned seed, double& found, double& false_found,
              AFI::Noise_model& m)
{
  AFI::Control_matrix y = noisy(s, [base](Eigen::Index) { return base; }, false, seed);
  std::mt19937 rng(seed + 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<bool> thrown(std::size_t(y.rows()), false);
  for(Eigen::Index i = 0; i < y.rows(); ++i)
    if(unit(rng) < share)
    {
      thrown[std::size_t(i)] = true;
      y.row(i).head<3>() += (unit(rng) < 0.5 ? -size : size) * s.h * s.x.row(i).head<3>().normalized();
    }
  m = s.model(y);
  double thrown_count = 0, others = 0;
  found = false_found = 0;
  for(std::size_t i = 0; i < thrown.size(); ++i)
  {
    (thrown[i] ? thrown_count : others) += 1;
    if(m.hit_probability[i] > 0.5) (thrown[i] ? found : false_found) += 1;
  }
  std::printf("%.0f%% thrown %.1f h: %s; %.0f of %.0f thrown found, %.0f of %.0f others\n", 100 * share, size,
              m.description().c_str(), found, thrown_count, false_found, others);
  found /= thrown_count;
  false_found /= others;
}

void impulses(const Sphere& s)
{
  double found = 0, false_found = 0;
  AFI::Noise_model m;
  impulses(s, 0.1, 0.02, 1.5, 4, found, false_found, m);
  AF_CHECK(m.hit_share > 0.015 && m.hit_share < 0.025, "the share of impulses is read");
  AF_CHECK(found >= 0.9 && false_found <= 0.005, "the vertices hit are found");
  // a tenth hit: hits beside hits, each of which the ring rule gives to one; the core of the samples is then
  // narrower than the robust deviation, which a mixture with a unit core reads as no impulses
  impulses(s, 0.0, 0.1, 1.0, 9, found, false_found, m);
  AF_CHECK(m.hit_share > 0.05 && found >= 0.5 && false_found <= 0.01, "dense impulses are found");
}

// A part with creases and corners: the fandisk, a tenth of its vertices thrown 1 h along their normals and nothing
// else (bench/write_cases' impulsive noise). Its own creases make the robust deviation of the samples larger than
// their core, which a mixture with a unit core took for no impulses at all (0% read; now 7%).
void impulses_on_a_part(const std::string& data)
{
  Mesh fandisk;
  if(!AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/fandisk0.3_original.obj", fandisk), "fandisk0.3_original.obj is read"))
    return;
  const AFI::Indexed_mesh<Mesh> im(fandisk, AFI::Borders::GHOSTED, true);
  const AFI::Ghost_layer& layer = im.ghost_layer();
  AFI::Control_matrix y = im.read_points(get(CGAL::vertex_point, fandisk));
  const AFI::Control_matrix normals = AFI::vertex_normals(*layer.topology, layer.real_faces, y);
  double h = 0;
  for(Mesh::Edge_index e : fandisk.edges())
    h += std::sqrt(CGAL::squared_distance(fandisk.point(fandisk.source(fandisk.halfedge(e))),
                                          fandisk.point(fandisk.target(fandisk.halfedge(e))))) /
         double(fandisk.number_of_edges());
  std::mt19937 rng(10);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<bool> thrown(std::size_t(y.rows()), false);
  for(Eigen::Index i = 0; i < y.rows(); ++i)
    if(unit(rng) < 0.1)
    {
      thrown[std::size_t(i)] = true;
      y.row(i).head<3>() += (unit(rng) < 0.5 ? -h : h) * normals.row(i).head<3>();
    }
  const std::vector<bool> usable(std::size_t(y.rows()), true);
  const AFI::Noise_model m =
    AFI::estimate_noise_model(*layer.topology, y, usable, AFI::Noise_estimate(*layer.topology, y, usable), h);
  double found = 0, false_found = 0, thrown_count = 0;
  for(std::size_t i = 0; i < thrown.size(); ++i)
  {
    thrown_count += thrown[i] ? 1 : 0;
    if(m.hit_probability[i] > 0.5) (thrown[i] ? found : false_found) += 1;
  }
  std::printf("fandisk, a tenth thrown 1 h: %s; %.0f of %.0f thrown found, %.0f others\n", m.description().c_str(),
              found, thrown_count, false_found);
  AF_CHECK(m.hit_share > 0.05 && found >= 0.5 * thrown_count && false_found <= 0.2 * found,
           "impulses on a part with creases are found");
}

// unit Gaussian noise averaged once with its ring's mean (half each), at unit root mean square
std::vector<double> averaged_once(const Sphere& s, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const AFI::Triangle_topology& topo = *s.im->ghost_layer().topology;
  std::vector<double> u(std::size_t(s.x.rows())), w(u.size());
  for(double& x : u) x = gauss(rng);
  std::vector<int> ring;
  double square = 0;
  for(std::size_t i = 0; i < u.size(); ++i)
  {
    AFI::read_ring(topo, i, ring);
    w[i] = 0.5 * u[i];
    for(int j : ring) w[i] += 0.5 * u[std::size_t(j)] / double(ring.size());
    square += w[i] * w[i];
  }
  for(double& x : w) x /= std::sqrt(square / double(w.size()));
  return w;
}

// x moved by `scale` times w along the radius
AFI::Control_matrix moved(const Sphere& s, const std::vector<double>& w, double scale)
{
  AFI::Control_matrix y = s.x;
  for(Eigen::Index i = 0; i < y.rows(); ++i)
    y.row(i).head<3>() += scale * w[std::size_t(i)] * s.x.row(i).head<3>().normalized();
  return y;
}

// Noise correlated over the surface: Gaussian along the normals averaged once with its ring's mean (half each),
// 0.2 h RMS. Its second differences read about 0.66 of it; the correlation read puts it back within 15%, where
// independent noise and the clean sphere are left as read.
void correlated(const Sphere& s)
{
  const AFI::Triangle_topology& topo = *s.im->ghost_layer().topology;
  const AFI::Control_matrix y = moved(s, averaged_once(s, 11), 0.2 * s.h);
  const auto estimate = [&](const AFI::Control_matrix& m) {
    const std::vector<bool> usable(std::size_t(m.rows()), true);
    return AFI::Noise_estimate(topo, m, usable);
  };
  const AFI::Noise_estimate c = estimate(y), independent = estimate(noisy(s, [](Eigen::Index) { return 0.2; },
                                                                          false, 12)),
                            clean = estimate(s.x);
  std::printf("averaged once, 0.2 h: read %.3f h, %s\nindependent, 0.2 h: read %.3f h, %s\nclean: %s\n",
              c.read_sigma(), c.correlation().description().c_str(), independent.read_sigma(),
              independent.correlation().description().c_str(), clean.correlation().description().c_str());
  AF_CHECK(c.read_sigma() < 0.8 * 0.2, "correlated noise reads low (what the correction is for)");
  AF_CHECK(std::abs(c.relative_sigma() / 0.2 - 1) < 0.15, "correlated noise is read with its correlation");
  AF_CHECK(c.correlation().k > 0.7 && c.correlation().k < 1.3, "noise averaged once lies at k = 1");
  AF_CHECK(independent.correlation().factor() == 1 && independent.correlation().k < 0.3,
           "independent noise is left as read");
  AF_CHECK(clean.correlation().factor() == 1, "a clean mesh's reading is left as it is");
}

// Generalized SURE of a linear smoother (the radial heights averaged twice with their rings' means) under the
// noise averaged once: probed with unit noise made as correlated as the noise read, its mean over draws is the
// mean loss; probed with independent noise, it misses the smoother's response to correlated noise.
void probe_like_the_noise(const Sphere& s)
{
  const AFI::Ghost_layer& layer = s.im->ghost_layer();
  const AFI::Triangle_topology& topo = *layer.topology;
  const std::size_t n = std::size_t(s.x.rows());
  const auto heights = [&](const AFI::Control_matrix& m) {
    std::vector<double> r(n);
    for(std::size_t i = 0; i < n; ++i)
      r[i] = m.row(Eigen::Index(i)).head<3>().dot(s.x.row(Eigen::Index(i)).head<3>().normalized());
    return r;
  };
  const auto smoothed = [&](const AFI::Control_matrix& m) {
    const std::vector<double> r = heights(m);
    const std::vector<double> f = AFI::averaged_with_ring(topo, AFI::averaged_with_ring(topo, r, n), n);
    AFI::Control_matrix out = m;
    for(std::size_t i = 0; i < n; ++i)
      out.row(Eigen::Index(i)).head<3>() += (f[i] - r[i]) * s.x.row(Eigen::Index(i)).head<3>().normalized();
    return out;
  };
  const std::vector<double> sigma(n, 0.2 * s.h);
  double correlated_bias = 0, independent_bias = 0;
  const int draws = 8;
  for(int draw = 0; draw < draws; ++draw)
  {
    const AFI::Control_matrix y = moved(s, averaged_once(s, unsigned(40 + draw)), 0.2 * s.h);
    const std::vector<bool> usable(n, true);
    const AFI::Noise_estimate read(topo, y, usable);
    const AFI::Control_matrix f = smoothed(y);
    for(bool like_the_noise : { true, false })
    {
      const std::vector<double> independent = AFI::risk_probe_values(n);
      const std::vector<double> b = like_the_noise ? AFI::correlated_like(topo, independent, n, read.correlation())
                                                   : independent;
      const AFI::Position_error_estimate e(topo, layer.real_faces, y, s.x, sigma, b);
      const double bias = e.relative(f, smoothed(e.probed())) - e.relative_loss(f, s.x);
      (like_the_noise ? correlated_bias : independent_bias) += bias / draws;
    }
  }
  std::printf("SURE of a linear smoother under noise averaged once, its mean bias over %d draws: probed like the "
              "noise read %.4f, probed with independent noise %.4f (per vertex, in units of the noise)\n", draws,
              correlated_bias, independent_bias);
  AF_CHECK(std::abs(correlated_bias) < 0.03, "probed like the noise, the estimate is unbiased");
  AF_CHECK(independent_bias < -0.2, "probed with independent noise, it misses the smoother's response to the noise");
}

void lattice(const Sphere& s)
{
  const AFI::Control_matrix y = noisy(s, [](Eigen::Index) { return 0.2; }, false, 6);
  const auto rounded = [&](double step) {
    AFI::Control_matrix r = y;
    for(Eigen::Index i = 0; i < r.rows(); ++i)
      for(int a = 0; a < 3; ++a) r(i, a) = 0.1 + step * std::round((r(i, a) - 0.1) / step);
    return r;
  };
  const double step = 0.25 * s.h;
  const AFI::Noise_model fine = s.model(rounded(step)), coarse = s.model(rounded(2 * s.h));
  std::printf("rounded to 0.25 h: %s\n", fine.description().c_str());
  bool found = true;
  for(int a = 0; a < 3; ++a) found = found && std::abs(fine.cell[std::size_t(a)] / step - 1) < 1e-9;
  AF_CHECK(found, "the lattice's step is found");
  AF_CHECK(coarse.cell[0] == 0 && coarse.cell[1] == 0 && coarse.cell[2] == 0,
           "a lattice coarser than the edges is not noise");
}

} // namespace

// The noisy sphere numbered in another order (vertex i becomes new_of_old[i], the faces shuffled): with the
// vertices' keys, every vertex draws the same numbers and the estimate reads the same noise.
void any_numbering(const Sphere& s)
{
  const AFI::Ghost_layer& layer = s.im->ghost_layer();
  const std::size_t n = std::size_t(s.x.rows());
  const AFI::Control_matrix y = noisy(s, [](Eigen::Index) { return 0.2; }, true, 21);
  std::mt19937 random(8);
  std::vector<int> new_of_old(n);
  for(std::size_t i = 0; i < n; ++i) new_of_old[i] = int(i);
  std::shuffle(new_of_old.begin(), new_of_old.end(), random);
  std::vector<std::size_t> old_of_new_face(layer.real_faces);
  for(std::size_t f = 0; f < old_of_new_face.size(); ++f) old_of_new_face[f] = f;
  std::shuffle(old_of_new_face.begin(), old_of_new_face.end(), random);
  const AFI::Ghost_layer other = layer.renumbered(new_of_old, old_of_new_face);
  AFI::Control_matrix z(y.rows(), y.cols());
  for(std::size_t i = 0; i < n; ++i) z.row(new_of_old[i]) = y.row(Eigen::Index(i));
  const std::vector<bool> usable(n, true);
  const std::vector<std::uint64_t> keys = AFI::vertex_keys(layer, y), other_keys = AFI::vertex_keys(other, z);
  const AFI::Noise_estimate a(*layer.topology, y, usable, keys), b(*other.topology, z, usable, other_keys),
    by_number(*other.topology, z, usable);
  const std::vector<double> probe = AFI::risk_probe_values(n, keys), other_probe = AFI::risk_probe_values(n, other_keys);
  bool same_draws = true, same_by_number = true;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = std::size_t(new_of_old[i]);
    // the null sums the draws of a vertex's rings in the order of the numbering: the same to rounding
    same_draws = same_draws && std::abs(a.normal_null()[i] - b.normal_null()[j]) <= 1e-12 && probe[i] == other_probe[j];
    same_by_number = same_by_number && std::abs(a.normal_null()[i] - by_number.normal_null()[j]) <= 1e-12;
  }
  std::printf("renumbered: noise %.15g h and %.15g h (drawn by number: %.15g h), correlation k %.6g and %.6g\n",
              a.relative_sigma(), b.relative_sigma(), by_number.relative_sigma(), a.correlation().k,
              b.correlation().k);
  AF_CHECK(same_draws, "renumbered, every vertex draws the same reference noise and probe");
  AF_CHECK(!same_by_number, "drawn by the vertices' numbers, the reference noise moves with the numbering");
  AF_CHECK(std::abs(a.relative_sigma() - b.relative_sigma()) <= 1e-12 * a.relative_sigma() &&
             std::abs(a.correlation().k - b.correlation().k) <= 1e-12,
           "renumbered, the same noise and correlation are read");
}

// The probe made as correlated as k = 1.5 on the hemisphere (a border: border vertices' rings reach the ghosts), against
// the averaging with each vertex's neighbours found here from the faces (the ghost faces included), at unit RMS
// over the real vertices.
void correlated_on_a_border(const std::string& data)
{
  Mesh hemisphere;
  if(!AF_CHECK(CGAL::IO::read_polygon_mesh(data + "/hemisphere.off", hemisphere), "hemisphere.off is read")) return;
  const AFI::Indexed_mesh<Mesh> im(hemisphere, AFI::Borders::GHOSTED, true);
  const AFI::Ghost_layer& layer = im.ghost_layer();
  const AFI::Triangle_topology& topo = *layer.topology;
  const std::size_t n = layer.real_vertices, all = topo.number_of_vertices();
  const std::vector<std::uint64_t> keys = AFI::vertex_keys(layer, im.read_points(get(CGAL::vertex_point, hemisphere)));
  const std::vector<double> b = AFI::risk_probe_values(keys.size(), keys);
  AFI::Noise_correlation c;
  c.corrected = true;
  c.k = 1.5;
  const std::vector<double> probe = AFI::correlated_like(topo, b, n, c);
  std::vector<std::set<std::size_t>> neighbours(all);
  for(std::size_t f = 0; f < topo.number_of_faces(); ++f)
    for(int a : topo.face(f))
      for(int e : topo.face(f))
        if(a != e) neighbours[std::size_t(a)].insert(std::size_t(e));
  const auto averaged = [&](const std::vector<double>& x) {
    std::vector<double> out = x;
    for(std::size_t i = 0; i < n; ++i)
    {
      double sum = 0;
      for(std::size_t j : neighbours[i]) sum += x[j];
      out[i] = 0.5 * x[i] + 0.5 * sum / double(neighbours[i].size());
    }
    return out;
  };
  const auto unit = [&](std::vector<double> x) {
    double square = 0;
    for(std::size_t i = 0; i < n; ++i) square += x[i] * x[i];
    for(double& v : x) v /= std::sqrt(square / double(n));
    return x;
  };
  const std::vector<double> once = unit(averaged(b)), twice = unit(averaged(once));
  std::vector<double> expected(all);
  for(std::size_t i = 0; i < all; ++i) expected[i] = 0.5 * once[i] + 0.5 * twice[i];
  expected = unit(expected);
  double largest = 0;
  for(std::size_t i = 0; i < n && i < probe.size(); ++i) largest = std::max(largest, std::abs(probe[i] - expected[i]));
  std::printf("hemisphere (%zu vertices, %zu ghosts): the probe correlated as k = 1.5 off the faces' averaging by "
              "%.3g\n", n, all - n, largest);
  AF_CHECK(probe.size() == n && largest < 1e-12,
           "on a border, the correlated probe averages each ring with its ghosts, one number per real vertex");
}

int main(int argc, char** argv)
{
  const Sphere s;
  std::printf("icosphere: %ld vertices, h = %.5f\n", long(s.x.rows()), s.h);
  along_and_across(s);
  over_the_surface(s);
  impulses(s);
  correlated(s);
  probe_like_the_noise(s);
  lattice(s);
  any_numbering(s);
  impulses_on_a_part(argc > 1 ? argv[1] : "data");
  correlated_on_a_border(argc > 1 ? argv[1] : "data");
  return AF_test::report();
}
