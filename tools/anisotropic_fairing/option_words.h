// The words of the options that choose among values, one table each, and the library values that the
// words of --stop and --tensor name: read by the program's parser and the Python module alike.
#ifndef AF_TOOL_OPTION_WORDS_H
#define AF_TOOL_OPTION_WORDS_H

#include "tool_common.h"

#include <CGAL/Anisotropic_fairing/Fairing_options.h>
#include <CGAL/Anisotropic_fairing/Fairing_settings.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <utility>
#include <vector>

namespace af_tool {

template <typename T>
using Word_table = std::vector<std::pair<const char*, T>>;

inline const Word_table<int> order_words = {{"2", 2}, {"4", 4}};
inline const Word_table<int> quadrature_words = {{"4", 4}, {"6", 6}, {"8", 8}};
inline const Word_table<AF::Finite_element> element_words = { { "loop", AF::Finite_element::LOOP },
                                                              { "linear", AF::Finite_element::LINEAR } };
inline const Word_table<AF::Output_positions> output_words = {{"limit", AF::Output_positions::LIMIT_SURFACE},
                                                               {"control", AF::Output_positions::CONTROL_POINTS}};
inline const Word_table<bool> tangential_words = {{"remove", true}, {"keep", false}};   // normal motion only
inline const Word_table<AF::Linear_solver> solver_words = {{"auto", AF::Linear_solver::AUTOMATIC},
                                                            {"cg", AF::Linear_solver::CONJUGATE_GRADIENT},
                                                            {"cholesky", AF::Linear_solver::CHOLESKY}};
inline const Word_table<AF::Boundary_handling> boundary_words = {
  { "curve", AF::Boundary_handling::HOLD_BOUNDARY_CURVE }, { "vertices", AF::Boundary_handling::HOLD_BOUNDARY_VERTICES }
};
inline const Word_table<AF::Attribute_mode> mode_words = {{"separate", AF::Attribute_mode::SEPARATE},
                                                           {"coupled", AF::Attribute_mode::COUPLED},
                                                           {"attributes", AF::Attribute_mode::ATTRIBUTES_ONLY},
                                                           {"geometry", AF::Attribute_mode::GEOMETRY_ONLY}};
inline const std::vector<const char*> stop_words = {"auto", "noise", "paper", "off"};
inline const std::vector<const char*> tensor_words = {"isotropic", "anisotropic", "uniform"};

// "a, b or c"
inline std::string word_list(const std::vector<const char*>& words)
{
  std::string list;
  for(std::size_t i = 0; i < words.size(); ++i)
    list += std::string(i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return list;
}
template <typename T>
std::vector<const char*> words_of(const Word_table<T>& table)
{
  std::vector<const char*> words;
  for(const auto& w : table) words.push_back(w.first);
  return words;
}

// The stopping rule that --stop's word names (auto: none given, the library's default).
inline std::optional<AF::Stopping_criteria> stopping_rule(const std::string& word)
{
  if(word == "noise") return AF::Stopping_criteria::automatic();
  if(word == "paper") return AF::Stopping_criteria();
  if(word == "off") return AF::Stopping_criteria::none();
  return std::nullopt;
}

// The tensor that --tensor's word and the anisotropic tensor's settings name (no word: none given, the
// library's default; the anisotropic tensor without settings is chosen from the mesh with automatic
// parameters). Throws std::invalid_argument for an unknown word.
inline std::optional<AF::Package_diffusion_tensor> package_tensor(const std::string& word, bool automatic,
                                                                  bool has_settings, double lambda, double epsilon,
                                                                  bool normal_motion_only)
{
  if(word.empty()) return std::nullopt;
  if(word == "isotropic") return AF::Isotropic_diffusion_tensor();
  if(word == "uniform") return AF::Uniform_diffusion_tensor();
  if(word != "anisotropic") throw std::invalid_argument("no tensor is called " + word);
  if(automatic && !has_settings) return AF::Anisotropic_diffusion_tensor::automatic();
  return AF::Anisotropic_diffusion_tensor().set_lambda(lambda).set_epsilon(epsilon).set_normal_motion_only(
    normal_motion_only);
}

// the anisotropic tensor whose threshold and prefilter are chosen from the mesh
inline bool automatic_tensor(const AF::Fairing_options& f)
{
  const AF::Package_diffusion_tensor t = f.diffusion_tensor_or_default();
  return f.automatic_parameters() && std::holds_alternative<AF::Anisotropic_diffusion_tensor>(t) &&
         std::get<AF::Anisotropic_diffusion_tensor>(t).is_automatic();
}

} // namespace af_tool

#endif // AF_TOOL_OPTION_WORDS_H
