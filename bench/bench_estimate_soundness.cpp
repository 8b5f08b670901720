// Is an estimate of the error sound enough to choose the default run's result by? (issue 53, point 2)
//
// For every case directory CASES_DIR/<case>/{noisy.off, original.off} (bench/write_cases writes them: the
// denoising pairs and the generated noises), the default run is made as anisotropic_fairing() makes it, with
// the normal-field candidate added and the candidates chosen by the estimate asked for: `normals` (default),
// the face normals' error (internal/run/Normal_error_estimate.h) read on the prefiltered input, `on-result` the
// same read again on the result kept, or `positions`, the default run's own SURE.
// Every candidate is read back once estimated (Fairing_core::observe_candidates) and measured against the
// original: the loss the estimate estimates (known the clean surface), the face-wise first-order loss
// linearised at the clean surface, the area-weighted mean squared face-normal angle (both relative to the noisy
// input's) and the mean face-normal angle in degrees (what users and the peers' tables measure). Printed per
// case: those per candidate, the candidate the estimate picks and the truly best (by mean angle); then how
// often the pick, and the pick of the estimated loss itself, is within 5% of the best, and the correlations.
// On stderr, per case: the noisy input's loss in the estimate's unit (1 if the noise model is right), and,
// with the true noise deviation, the input's face-normal loss relative to its model with the faces' normals
// and stiffness read on the clean and on the noisy mesh.
//
// With `clean`, the estimate reads its normals and stiffness on the clean mesh (an oracle: how much of its
// error comes from the surface it measures on); with `coupled`, the default run is made on y* = y + omega
// and the estimate reads them on the default result of y - omega, whose noise is independent of y*'s
// (coupled_copies; the truth is then that of the results of y*, at twice the noise's variance). With `minus`, the
// candidates run on y itself and the estimate reads them on the default result of y - omega (whose noise is
// independent of y's in part only); with `minus-isotropic` or `minus-anisotropic` on that flow's result of y - omega
// alone.
// The face normals' error is estimated with the noise model the default run reads (Noise_model.h): its deviations
// along and across the normals at each vertex.
//
//   bench_estimate_soundness CASES_DIR [CASE_SUBSTRING] [normals|on-result|positions]
//                            [clean|coupled|minus|minus-isotropic|minus-anisotropic]

#include "bench_cases.h"

#include <CGAL/Anisotropic_fairing/anisotropic_fairing.h>

#include <cstdio>
#include <string>
#include <vector>

namespace AF = CGAL::Anisotropic_fairing;
namespace AFI = CGAL::Anisotropic_fairing::internal;

namespace {

struct Candidate_truth
{
  std::string name, stop;
  std::size_t steps = 0;
  double estimate = nan_value, carried = nan_value, first_order = nan_value, facewise = nan_value;
  double mean_angle = nan_value, squared_angle = nan_value;
  std::size_t folds = 0;
  bool at_noise = false;
};

// Area-weighted mean squared angle (radians^2) of m's face normals against the reference's.
double squared_angle(const Mesh& m, const std::vector<Vector>& reference)
{
  double sum = 0, area = 0;
  std::size_t i = 0;
  for(Mesh::Face_index f : m.faces())
  {
    const Vector r = reference[i++];
    const double a = std::sqrt(r.squared_length());
    const double t = normal_angle(face_normal(m, f), r);
    sum += a * t * t;
    area += a;
  }
  return sum / area;
}

// The face-wise first-order loss linearised at the clean surface: sum_f |grad_f (n_f . e)|^2 with n_f and the
// gradients of the clean face f, e = result - clean; what a face normal's error is to first order (motion
// within a face's plane does not turn it), relative to the same of the noisy input.
double facewise_loss(const Mesh& result, const Mesh& clean)
{
  double sum = 0;
  for(Mesh::Face_index f : faces(clean))
  {
    Point p[3];
    Vector e[3];
    int k = 0;
    for(Mesh::Vertex_index v : vertices_around_face(clean.halfedge(f), clean))
    {
      p[k] = clean.point(v);
      e[k] = result.point(v) - clean.point(v);
      ++k;
    }
    const Vector c = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const double twice_area = std::sqrt(c.squared_length());
    if(!(twice_area > 0)) continue;
    const Vector n = c / twice_area;
    // grad phi_i = n x (opposite edge) / (2A); grad (n . e) = sum_i (n . e_i) grad phi_i
    Vector g(0, 0, 0);
    for(int i = 0; i < 3; ++i) g = g + (n * e[i]) * CGAL::cross_product(n, p[(i + 2) % 3] - p[(i + 1) % 3]) / twice_area;
    sum += 0.5 * twice_area * g.squared_length();
  }
  return sum;
}

std::vector<Candidate_truth> run_case(const std::string& name, const Mesh& noisy, const Mesh& original,
                                     AFI::Risk_kind kind, const Mesh* measured_on)
{
  Mesh mesh = noisy;
  const AF::Fairing_options options;
  const AFI::Fairing_parameters given = AFI::resolve_fairing_parameters(options, false);
  AFI::Indexed_mesh<Mesh> im(mesh, AFI::Borders::GHOSTED, true);
  const AFI::Control_matrix P = im.read_points(get(CGAL::vertex_point, mesh));
  const std::vector<bool> held(im.number_of_vertices(), false);
  const AFI::Fairing_input in{ im.ghost_layer(), P, AFI::Control_matrix(), held, false };
  const std::function<bool(const AF::Fairing_step&)> callback = [](const AF::Fairing_step&) { return true; };
  AFI::Fairing_core<AF::Package_diffusion_tensor> core(in, given, options.diffusion_tensor_or_default(), callback);
  const std::vector<Vector> reference = face_normals(original);
  const double input_squared = squared_angle(noisy, reference), input_facewise = facewise_loss(noisy, original);
  std::vector<Candidate_truth> out;
  core.observe_candidates([&](const AFI::Candidate_list& list, const AFI::Risk_estimate& e,
                              const std::vector<int>& old_of_new) {
    AFI::Control_matrix clean(P.rows(), 3);   // the original in the run's numbering
    for(Eigen::Index i = 0; i < P.rows(); ++i)
    {
      const Point& p = original.point(Mesh::Vertex_index(std::size_t(old_of_new[std::size_t(i)])));
      clean.row(i) << p.x(), p.y(), p.z();
    }
    AFI::Control_matrix noisy_rows(P.rows(), 3);
    for(Eigen::Index i = 0; i < P.rows(); ++i)
    {
      const Point& p = noisy.point(Mesh::Vertex_index(std::size_t(old_of_new[std::size_t(i)])));
      noisy_rows.row(i) << p.x(), p.y(), p.z();
    }
    std::fprintf(stderr, "%s: the input's loss in the estimate's unit: %.3f\n", name.c_str(),
                 e.relative_loss(noisy_rows, clean));
    for(const AFI::Flow_candidate& c : list)
    {
      Candidate_truth t;
      t.name = c.name;
      t.stop = c.result.report.succeeded() ? AF::to_string(c.result.report.stop_reason)
                                           : AF::to_string(c.result.report.status);
      t.steps = c.result.report.steps.size();
      t.at_noise = AFI::ended_at_noise_level(c.result.report);
      t.estimate = c.risk;
      t.carried = c.carried;
      if(c.result.report.succeeded() && c.result.Y.rows() == P.rows())
      {
        Mesh m = noisy;
        for(Eigen::Index i = 0; i < c.result.Y.rows(); ++i)
        {
          const auto& y = c.result.Y.row(i);
          m.point(Mesh::Vertex_index(std::size_t(old_of_new[std::size_t(i)]))) = Point(y[0], y[1], y[2]);
        }
        t.mean_angle = normal_error(m, reference);
        t.squared_angle = squared_angle(m, reference) / input_squared;
        t.folds = folded_edges(m);
        t.first_order = e.relative_loss(c.result.Y, clean);
        t.facewise = facewise_loss(m, original) / input_facewise;
      }
      out.push_back(t);
    }
  }, kind, true);
  if(measured_on)
  {
    AFI::Control_matrix X(P.rows(), 3);   // in the caller's numbering
    for(Eigen::Index i = 0; i < P.rows(); ++i)
    {
      const Point& p = measured_on->point(Mesh::Vertex_index(std::size_t(i)));
      X.row(i) << p.x(), p.y(), p.z();
    }
    core.measure_on(X);
  }
  core.prepare();
  core.run();
  {
    const AFI::Ghost_layer& layer = im.ghost_layer();
    AFI::Control_matrix Xc(P.rows(), 3);
    for(Eigen::Index i = 0; i < P.rows(); ++i)
    {
      const Point& p = original.point(Mesh::Vertex_index(std::size_t(i)));
      Xc.row(i) << p.x(), p.y(), p.z();
    }
    const AFI::Control_matrix Nc = AFI::vertex_normals(*layer.topology, layer.real_faces, Xc);
    double s2 = 0;
    for(Eigen::Index i = 0; i < P.rows(); ++i) s2 += std::pow(Nc.row(i).dot(P.row(i) - Xc.row(i)), 2);
    const std::vector<double> sig(std::size_t(P.rows()), std::sqrt(s2 / double(P.rows()))), ones(sig.size(), 1.0);
    const AFI::Normal_error_estimate on_clean(*layer.topology, layer.real_faces, P, Xc, sig, ones);
    const AFI::Normal_error_estimate on_noisy(*layer.topology, layer.real_faces, P, P, sig, ones);
    std::fprintf(stderr, "%s: with the true sigma, the input's face-normal loss relative to tr(A Sigma), A of the clean "
                 "surface %.3f, of the noisy one %.3f\n", name.c_str(), on_clean.relative_loss(P, Xc),
                 on_noisy.relative_loss(P, Xc));
  }
  return out;
}

// The coupled bootstrap (Oliveira, Lei & Tibshirani 2021): omega of the noise's law, y* = y + omega and
// y' = y - omega have independent noises (2 sigma^2 each). Returns y*; `measured_on` gets the default run's
// result of y', a surface that does not follow y*'s noise. sigma: the package's own estimate.
Mesh coupled_copies(const Mesh& noisy, Mesh& measured_on, unsigned seed, const std::string& flow = "")
{
  const AFI::Indexed_mesh<Mesh> im(noisy, AFI::Borders::GHOSTED, true);
  const AFI::Ghost_layer& layer = im.ghost_layer();
  const AFI::Control_matrix X = im.read_points(get(CGAL::vertex_point, noisy));
  std::vector<bool> usable(std::size_t(X.rows()), true);
  for(int v : layer.boundary_vertices) usable[std::size_t(v)] = false;
  const double sigma = AFI::Noise_estimate(*layer.topology, X, usable).relative_sigma() * mean_edge_length(noisy);
  const AFI::Control_matrix N = AFI::vertex_normals(*layer.topology, layer.real_faces, X);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  Mesh plus = noisy, minus = noisy;
  for(Mesh::Vertex_index v : noisy.vertices())
  {
    const std::size_t i = std::size_t(v);
    if(!usable[i]) continue;
    const double g = gauss(rng);
    const Vector w(g * N(Eigen::Index(i), 0), g * N(Eigen::Index(i), 1), g * N(Eigen::Index(i), 2));
    plus.point(v) = noisy.point(v) + w;
    minus.point(v) = noisy.point(v) - w;
  }
  if(flow == "isotropic")
    AF::anisotropic_fairing(minus, AF::parameters::diffusion_tensor(AF::Isotropic_diffusion_tensor()));
  else if(flow == "anisotropic")   // the default run's own tensor, its constants in units of h (Automatic_parameters.h)
  {
    const double h = mean_edge_length(noisy);
    const AFI::Automatic_parameters a;
    AF::anisotropic_fairing(minus, AF::parameters::diffusion_tensor(
                                     AF::Anisotropic_diffusion_tensor(a.lambda / h, false, a.epsilon * h * h)));
  }
  else
    AF::anisotropic_fairing(minus);
  measured_on = minus;
  return plus;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b)
{
  const double n = double(a.size());
  double ma = 0, mb = 0;
  for(std::size_t i = 0; i < a.size(); ++i) { ma += a[i] / n; mb += b[i] / n; }
  double sab = 0, saa = 0, sbb = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: %s CASES_DIR [CASE_SUBSTRING] [normals|on-result|positions] "
                 "[clean|coupled|minus|minus-isotropic|minus-anisotropic]\n",
                 argv[0]);
    return 2;
  }
  const std::string dir = argv[1], only = argc > 2 ? argv[2] : "";
  const std::string which = argc > 3 ? argv[3] : "normals";
  const AFI::Risk_kind kind = which == "positions"   ? AFI::Risk_kind::POSITIONS
                              : which == "on-result" ? AFI::Risk_kind::FACE_NORMALS_ON_RESULT
                                                     : AFI::Risk_kind::FACE_NORMALS;
  // measured on the clean mesh (an oracle), or the coupled copies
  const std::string on = argc > 4 ? argv[4] : "";
  const std::vector<std::string> cases = case_folders(dir, only);
  std::printf("| case | candidate: estimate / the loss it estimates / the same linearised at the clean surface / "
              "relative squared angle / mean angle, steps, stop | picked | best | picked / best |\n"
              "|---|---|---|---|---:|\n");
  std::vector<double> all_estimates, all_truths, all_first_order;
  std::size_t within = 0, within_surrogate = 0, counted = 0;
  for(const std::string& name : cases)
  {
    Mesh noisy, original;
    if(!CGAL::IO::read_polygon_mesh(dir + "/" + name + "/noisy.off", noisy) ||
       !CGAL::IO::read_polygon_mesh(dir + "/" + name + "/original.off", original))
      continue;
    Mesh other;
    const bool coupled = on == "coupled" || on.rfind("minus", 0) == 0;
    const Mesh plus = coupled ? coupled_copies(noisy, other, 20261129u, on.size() > 6 ? on.substr(6) : "") : noisy;
    const Mesh& y = on == "coupled" ? plus : noisy;
    const Mesh* measured_on = on == "clean" ? &original : coupled ? &other : nullptr;
    const std::vector<Candidate_truth> c = run_case(name, y, original, kind, measured_on);
    std::string row;
    std::size_t picked = c.size(), best = c.size(), surrogate = c.size();
    for(std::size_t k = 0; k < c.size(); ++k)
    {
      const Candidate_truth& t = c[k];
      char text[200];
      // an estimate not made: the carried one, which it could only exceed (Smoother_selection.h)
      const std::string estimate = std::isfinite(t.estimate) ? fmt("%.3f", t.estimate)
                                   : std::isfinite(t.carried) ? fmt(">=%.3f", t.carried) : "nan";
      std::snprintf(text, sizeof text, "%s%s: %s / %.3f / %.3f / %.3f / %.3f, %zu, %s", row.empty() ? "" : "; ",
                    t.name.c_str(), estimate.c_str(), t.first_order, t.facewise, t.squared_angle, t.mean_angle,
                    t.steps, t.stop.c_str());
      row += text;
      if(std::isfinite(t.estimate) && std::isfinite(t.squared_angle))
      {
        all_estimates.push_back(t.estimate);
        all_truths.push_back(t.squared_angle);
        all_first_order.push_back(t.first_order);
      }
      if(t.at_noise && std::isfinite(t.first_order) && (surrogate == c.size() || t.first_order < c[surrogate].first_order))
        surrogate = k;
      if(t.at_noise && std::isfinite(t.estimate) && (picked == c.size() || t.estimate < c[picked].estimate)) picked = k;
      if(std::isfinite(t.mean_angle) && (best == c.size() || t.mean_angle < c[best].mean_angle)) best = k;
    }
    if(picked < c.size() && best < c.size())
    {
      const double ratio = c[picked].mean_angle / c[best].mean_angle;
      ++counted;
      within += ratio <= 1.05 ? 1 : 0;
      within_surrogate += surrogate < c.size() && c[surrogate].mean_angle / c[best].mean_angle <= 1.05 ? 1 : 0;
      std::printf("| %s | %s | %s %.3f | %s %.3f | %.3f |\n", name.c_str(), row.c_str(), c[picked].name.c_str(),
                  c[picked].mean_angle, c[best].name.c_str(), c[best].mean_angle, ratio);
    }
    else
      std::printf("| %s | %s | - | - | - |\n", name.c_str(), row.c_str());
    std::fflush(stdout);
  }
  std::printf("\n%zu cases: within 5%% of the best mean angle, the estimate's pick on %zu, the pick of the loss it "
              "estimates (known the clean surface) on %zu; over %zu candidates the estimate's correlation with that "
              "loss %.3f, with the squared angle %.3f\n", counted, within, within_surrogate, all_estimates.size(),
              correlation(all_estimates, all_first_order), correlation(all_estimates, all_truths));
  return 0;
}
