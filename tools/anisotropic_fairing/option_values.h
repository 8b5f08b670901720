// The values of the program's options, read and checked: numbers, integers, words, lists of names and paths;
// every problem is a usage error (tool_common.h) that names the option and quotes the value.
#ifndef AF_TOOL_OPTION_VALUES_H
#define AF_TOOL_OPTION_VALUES_H

#include "option_words.h"
#include "tool_common.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace af_tool {

// "quality,red" -> {"quality", "red"}; blanks around a name are ignored
std::vector<std::string> parse_attribute_list(const std::string& text);

// a finite double, within the range of normal doubles
double parse_double(const std::string& flag, const std::string& text);

unsigned int parse_unsigned(const std::string& flag, const std::string& text);

// A number option: `value` read from `text` and checked (> 0, or >= 0 with `zero_allowed`); `given` is set
// after the check, or, with `given_if_invalid`, before it (a usage error's report then shows the value).
void set_number(double& value, bool& given, const std::string& flag, const std::string& text, bool zero_allowed,
                bool given_if_invalid = false);

// A number option of the library's: set once read and checked as above.
void set_number(std::optional<double>& value, const std::string& flag, const std::string& text, bool zero_allowed);

// A size in bytes: a number with an optional K, M, G or T (powers of 1024), e.g. 6G or 500M; "off": infinity.
double parse_memory_size(const std::string& flag, const std::string& text);

// The index of `text` among `names`; for any other text a usage error that lists them ("a, b or c").
std::size_t choice_index(const std::string& flag, const std::string& text, const std::vector<const char*>& names);

// The value that `text` names in `table`; for any other text that usage error.
template <typename T>
T choice(const std::string& flag, const std::string& text, const Word_table<T>& table)
{
  return table[choice_index(flag, text, words_of(table))].second;
}

// Whether two paths name one file: the same file if both exist (links included), else the same path.
bool same_file(const std::string& a, const std::string& b);

} // namespace af_tool

#endif // AF_TOOL_OPTION_VALUES_H
