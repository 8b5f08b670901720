// Is the default run's estimate of the face normals' error sound? (issue 53, point 2)
//
// For every case directory CASES_DIR/<case>/{noisy.off, original.off} (bench/write_cases writes them: the
// denoising pairs and the generated noises), the default run is made as anisotropic_fairing() makes it, and
// every candidate it compares is read back once estimated (Fairing_core::observe_candidates). Against the
// original, each candidate's truth: the mean face-normal angle (degrees, what users and the peers' tables
// measure) and the area-weighted mean squared angle relative to the noisy input's (what the estimate
// estimates, to first order). Printed per case: estimate and truth per candidate, the candidate the estimate
// picks and the truly best; then over all cases the correlation of estimate and truth and how often the pick
// is within 5% of the best mean angle.
//
//   bench_estimate_soundness CASES_DIR [CASE_SUBSTRING]

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
  double sure = nan_value, estimate = nan_value, carried = nan_value, mean_angle = nan_value, squared_angle = nan_value;
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

std::vector<Candidate_truth> run_case(const Mesh& noisy, const Mesh& original)
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
  const double input_squared = squared_angle(noisy, reference);
  std::vector<Candidate_truth> out;
  core.observe_candidates([&](const AFI::Candidate_list& list, const std::vector<int>& old_of_new) {
    for(const AFI::Flow_candidate& c : list)
    {
      Candidate_truth t;
      t.name = c.name;
      t.stop = c.result.report.succeeded() ? AF::to_string(c.result.report.stop_reason)
                                           : AF::to_string(c.result.report.status);
      t.steps = c.result.report.steps.size();
      t.at_noise = AFI::ended_at_noise_level(c.result.report);
      t.sure = c.risk / double(P.rows()) - 1;
      t.estimate = c.normal_error;
      t.carried = c.normal_carried;
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
      }
      out.push_back(t);
    }
  }, true);
  core.run();
  return out;
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
    std::fprintf(stderr, "usage: %s CASES_DIR [CASE_SUBSTRING]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1], only = argc > 2 ? argv[2] : "";
  std::vector<std::string> cases;
  for(const auto& e : std::filesystem::directory_iterator(dir))
    if(e.is_directory() && e.path().filename().string().find(only) != std::string::npos)
      cases.push_back(e.path().filename().string());
  std::sort(cases.begin(), cases.end());
  std::printf("| case | candidate: SURE / normal-error estimate / truth (relative squared angle) / mean angle, steps, "
              "stop | picked by the normal-error estimate | picked by SURE | best | ratios to the best |\n"
              "|---|---|---|---|---|---|\n");
  std::vector<double> all_estimates, all_truths;
  std::size_t within = 0, within_kept = 0, counted = 0;
  for(const std::string& name : cases)
  {
    Mesh noisy, original;
    if(!CGAL::IO::read_polygon_mesh(dir + "/" + name + "/noisy.off", noisy) ||
       !CGAL::IO::read_polygon_mesh(dir + "/" + name + "/original.off", original))
      continue;
    const std::vector<Candidate_truth> c = run_case(noisy, original);
    std::string row;
    std::size_t picked = c.size(), best = c.size(), kept = c.size();
    for(std::size_t k = 0; k < c.size(); ++k)
    {
      const Candidate_truth& t = c[k];
      char text[200];
      // an estimate not made: the carried one, which it could only exceed (Smoother_selection.h)
      const std::string estimate = std::isfinite(t.estimate) ? fmt("%.3f", t.estimate)
                                   : std::isfinite(t.carried) ? fmt(">=%.3f", t.carried) : "nan";
      std::snprintf(text, sizeof text, "%s%s: %.3f / %s / %.3f / %.3f, %zu, %s", row.empty() ? "" : "; ",
                    t.name.c_str(), t.sure, estimate.c_str(), t.squared_angle, t.mean_angle, t.steps, t.stop.c_str());
      row += text;
      if(std::isfinite(t.estimate) && std::isfinite(t.squared_angle))
      {
        all_estimates.push_back(t.estimate);
        all_truths.push_back(t.squared_angle);
      }
      if(t.at_noise && std::isfinite(t.estimate) && (picked == c.size() || t.estimate < c[picked].estimate)) picked = k;
      if(t.at_noise && std::isfinite(t.sure) && (kept == c.size() || t.sure < c[kept].sure)) kept = k;
      if(std::isfinite(t.mean_angle) && (best == c.size() || t.mean_angle < c[best].mean_angle)) best = k;
    }
    if(picked < c.size() && best < c.size() && kept < c.size())
    {
      const double ratio = c[picked].mean_angle / c[best].mean_angle, kept_ratio = c[kept].mean_angle / c[best].mean_angle;
      ++counted;
      within += ratio <= 1.05 ? 1 : 0;
      within_kept += kept_ratio <= 1.05 ? 1 : 0;
      std::printf("| %s | %s | %s %.3f | %s %.3f | %s %.3f | %.3f | %.3f |\n", name.c_str(), row.c_str(),
                  c[picked].name.c_str(), c[picked].mean_angle, c[kept].name.c_str(), c[kept].mean_angle,
                  c[best].name.c_str(), c[best].mean_angle, ratio, kept_ratio);
    }
    else
      std::printf("| %s | %s | - | - | - | - | - |\n", name.c_str(), row.c_str());
    std::fflush(stdout);
  }
  std::printf("\n%zu cases: within 5%% of the best mean angle, the normal-error estimate's pick on %zu, SURE's on %zu; "
              "correlation of the normal-error estimate and its truth over %zu candidates: %.3f\n", counted, within,
              within_kept, all_estimates.size(), correlation(all_estimates, all_truths));
  return 0;
}
