// The keyword arguments of fair(), read and checked: numbers, integers, words; and how each keyword of the
// parameter table (CGAL/Anisotropic_fairing/internal/parameter_table.h, column `python`) sets the program's
// Options from its value. A value of the wrong type is a TypeError, one out of range a ValueError, each
// naming the keyword; the library checks the ranges it knows and names the parameter in turn.
#ifndef AF_PYTHON_KEYWORD_ARGUMENTS_H
#define AF_PYTHON_KEYWORD_ARGUMENTS_H

#include "option_words.h"
#include "options.h"

#include <pybind11/pybind11.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace af_python {

namespace py = pybind11;
using af_tool::Options;
using af_tool::Word_table;

inline double number_argument(const std::string& name, py::handle value)
{
  if(py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value))
    throw py::type_error(name + " expects a number");
  double x = 0;
  try
  {
    x = value.cast<double>();
  }
  catch(const py::cast_error&)
  {
    throw py::type_error(name + " expects a number, not " + py::str(py::type::of(value)).cast<std::string>());
  }
  if(!std::isfinite(x)) throw py::value_error(name + " must be a finite number");
  return x;
}

inline long long integer_argument(const std::string& name, py::handle value)
{
  if(py::isinstance<py::bool_>(value) || !py::isinstance(value, py::module_::import("numbers").attr("Integral")))
    throw py::type_error(name + " expects an integer");
  return value.cast<long long>();
}

inline std::string word_argument(const std::string& name, py::handle value, const std::vector<const char*>& words)
{
  if(!py::isinstance<py::str>(value)) throw py::type_error(name + " expects " + af_tool::word_list(words));
  const std::string word = value.cast<std::string>();
  for(const char* w : words)
    if(word == w) return word;
  throw py::value_error(name + " expects " + af_tool::word_list(words) + ", not '" + word + "'");
}

template <typename T>
T word_argument(const std::string& name, py::handle value, const Word_table<T>& table)
{
  const std::string word = word_argument(name, value, af_tool::words_of(table));
  for(const auto& w : table)
    if(word == w.first) return w.second;
  return table.front().second;
}

// The kinds of the table's column `python`: each sets its row's member (or the tensor's Options) and
// says which words it takes (none: any value of its type), for the stubs' test.
struct Keyword_kind
{
  bool keyword = true;
  std::vector<const char*> words() const { return {}; }
};
struct No_keyword
{
  bool keyword = false;
  std::vector<const char*> words() const { return {}; }
  template <typename Field> void operator()(Options&, Field&, const std::string&, py::handle) const {}
};
struct Py_number : Keyword_kind
{
  template <typename Field> void operator()(Options&, Field& field, const std::string& name, py::handle v) const
  {
    field = number_argument(name, v);
  }
};
// bytes, >= 0; infinity (math.inf): no check
struct Py_memory_size : Keyword_kind
{
  void operator()(Options&, std::optional<double>& field, const std::string& name, py::handle v) const
  {
    if(py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v)) throw py::type_error(name + " expects a number");
    double x = 0;
    try { x = v.cast<double>(); }
    catch(const py::cast_error&) { throw py::type_error(name + " expects a number of bytes"); }
    if(!(x >= 0)) throw py::value_error(name + " must be >= 0 bytes (math.inf: no check)");
    field = x;
  }
};
struct Py_integer : Keyword_kind
{
  void operator()(Options&, int& field, const std::string& name, py::handle v) const
  {
    field = int(integer_argument(name, v));
  }
};
struct Py_count : Keyword_kind
{
  void operator()(Options&, std::optional<unsigned int>& field, const std::string& name, py::handle v) const
  {
    const long long n = integer_argument(name, v);
    if(n < 0 || n > (long long)(std::numeric_limits<unsigned int>::max)())
      throw py::value_error(name + " must be a non-negative integer");
    field = unsigned(n);
  }
};
template <typename T>
struct Py_words : Keyword_kind
{
  const Word_table<T>& table;
  explicit Py_words(const Word_table<T>& t) : table(t) {}
  std::vector<const char*> words() const { return af_tool::words_of(table); }
  template <typename Field> void operator()(Options&, Field& field, const std::string& name, py::handle v) const
  {
    field = word_argument(name, v, table);
  }
};
struct Py_stop_word : Keyword_kind
{
  std::vector<const char*> words() const { return af_tool::stop_words; }
  void operator()(Options& o, std::optional<af_tool::AF::Stopping_criteria>& field, const std::string& name,
                  py::handle v) const
  {
    field = af_tool::stopping_rule(o.stop = word_argument(name, v, af_tool::stop_words));
  }
};
struct Py_attribute_weight : Keyword_kind
{
  void operator()(Options& o, double& field, const std::string& name, py::handle v) const
  {
    field = number_argument(name, v);
    o.has_attribute_weight = true;
  }
};

// The tensor's word and its settings: options_of() makes fairing.diffusion_tensor of them
struct Py_tensor_word : Keyword_kind
{
  std::vector<const char*> words() const { return af_tool::tensor_words; }
  void operator()(Options& o, const std::string& name, py::handle v) const
  {
    o.tensor = word_argument(name, v, af_tool::tensor_words);
  }
};
struct Py_tensor_lambda : Keyword_kind
{
  void operator()(Options& o, const std::string& name, py::handle v) const
  {
    o.lambda = number_argument(name, v);
    o.has_lambda = true;
    if(!(o.lambda > 0)) throw py::value_error(name + " must be positive");
  }
};
struct Py_tensor_epsilon : Keyword_kind
{
  void operator()(Options& o, const std::string& name, py::handle v) const
  {
    o.epsilon = number_argument(name, v);
    o.has_epsilon = true;
    if(!(o.epsilon >= 0)) throw py::value_error(name + " must be >= 0");
  }
};
struct Py_tensor_tangential : Keyword_kind
{
  std::vector<const char*> words() const { return af_tool::words_of(af_tool::tangential_words); }
  void operator()(Options& o, const std::string& name, py::handle v) const
  {
    o.normal_motion_only = word_argument(name, v, af_tool::tangential_words);
    o.has_tangential_motion = true;
  }
};

} // namespace af_python

#endif // AF_PYTHON_KEYWORD_ARGUMENTS_H
