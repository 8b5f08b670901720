// How an option of the parameter table (CGAL/Anisotropic_fairing/internal/parameter_table.h, column
// `program`) reads its value: each kind sets the Fairing_options member of its row, or, for the tensor's
// word and settings, the Options that make the member diffusion_tensor; a bad value is a usage error.
#ifndef AF_TOOL_OPTION_KINDS_H
#define AF_TOOL_OPTION_KINDS_H

#include "option_values.h"
#include "option_words.h"
#include "options.h"

#include <optional>
#include <string>

namespace af_tool {

// a number, > 0 (or >= 0 with zero_allowed)
struct Number
{
  bool zero_allowed;
  explicit Number(bool zero) : zero_allowed(zero) {}
  void operator()(Options&, std::optional<double>& field, const std::string& flag, const std::string& v) const
  {
    set_number(field, flag, v, zero_allowed);
  }
  void operator()(Options&, double& field, const std::string& flag, const std::string& v) const
  {
    bool given = false;
    set_number(field, given, flag, v, zero_allowed);
  }
};

// a size in bytes, or off (option_values.h)
struct Memory_size
{
  void operator()(Options&, std::optional<double>& field, const std::string& flag, const std::string& v) const
  {
    field = parse_memory_size(flag, v);
  }
};

// a count of steps
struct Count
{
  void operator()(Options&, std::optional<unsigned int>& field, const std::string& flag, const std::string& v) const
  {
    field = parse_unsigned(flag, v);
  }
};

// one of the words of a table, for the value it names
template <typename T>
struct Words
{
  const Word_table<T>& table;
  explicit Words(const Word_table<T>& t) : table(t) {}
  template <typename Field>
  void operator()(Options&, Field& field, const std::string& flag, const std::string& v) const
  {
    field = choice(flag, v, table);
  }
};

// --stop: the word is kept for the report, set before the check so that a usage error's report shows it
struct Stop_word
{
  void operator()(Options& o, std::optional<AF::Stopping_criteria>& field, const std::string& flag,
                  const std::string& v) const
  {
    o.stop = v;
    choice_index(flag, v, stop_words);
    field = stopping_rule(v);
  }
};

// --attribute-weight: also noted as given (a warning without --mode coupled)
struct Attribute_weight
{
  void operator()(Options& o, double& field, const std::string& flag, const std::string& v) const
  {
    set_number(field, o.has_attribute_weight, flag, v, false);
  }
};

// No program option for this row
struct No_flag
{
  template <typename Field>
  void operator()(Options&, Field&, const std::string&, const std::string&) const {}
};

// The tensor's word and its settings, as given: parse_arguments makes fairing.diffusion_tensor of them
struct Tensor_word
{
  void operator()(Options& o, const std::string& flag, const std::string& v) const
  {
    o.tensor = v;   // set before the check: a usage error's report shows what was asked
    choice_index(flag, v, tensor_words);
  }
};
struct Tensor_lambda
{
  void operator()(Options& o, const std::string& flag, const std::string& v) const
  {
    set_number(o.lambda, o.has_lambda, flag, v, false, true);
  }
};
struct Tensor_epsilon
{
  void operator()(Options& o, const std::string& flag, const std::string& v) const
  {
    set_number(o.epsilon, o.has_epsilon, flag, v, true, true);
  }
};
struct Tensor_tangential
{
  void operator()(Options& o, const std::string& flag, const std::string& v) const
  {
    o.normal_motion_only = choice(flag, v, tangential_words);
    o.has_tangential_motion = true;
  }
};

} // namespace af_tool

#endif // AF_TOOL_OPTION_KINDS_H
