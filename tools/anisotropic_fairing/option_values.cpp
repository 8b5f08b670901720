// The values of the program's options, read and checked (option_values.h).
#include "option_values.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

namespace af_tool {
namespace fs = std::filesystem;

std::vector<std::string> parse_attribute_list(const std::string& text)
{
  std::vector<std::string> names;
  std::string::size_type start = 0;
  for(;;)
  {
    const std::string::size_type comma = text.find(',', start);
    std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::string::size_type b = name.find_first_not_of(" \t"), e = name.find_last_not_of(" \t");
    name = b == std::string::npos ? std::string() : name.substr(b, e - b + 1);
    if(name.empty()) usage_error("--attributes expects NAME,NAME,..., not " + quoted_excerpt(text));
    if(std::find(names.begin(), names.end(), name) != names.end())
      usage_error("--attributes names '" + name + "' twice");
    names.push_back(name);
    if(comma == std::string::npos) break;
    start = comma + 1;
  }
  return names;
}

double parse_double(const std::string& flag, const std::string& text)
{
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || (errno != ERANGE && !std::isfinite(v)))
    usage_error(flag + " expects a finite number, not " + quoted_excerpt(text));
  if(errno == ERANGE && std::abs(v) > 1) usage_error(flag + " " + text + " is beyond the range of double precision");
  if(errno == ERANGE)   // strtod says so below the smallest normal double, where the arithmetic loses its digits
    usage_error(flag + " " + text + " is below the smallest normal double (2.2e-308), too small to compute with");
  return v;
}

unsigned int parse_unsigned(const std::string& flag, const std::string& text)
{
  errno = 0;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if(text.empty() || text[0] == '-' || text[0] == '+' || end != text.c_str() + text.size() || errno == ERANGE ||
     v > (std::numeric_limits<unsigned int>::max)())
    usage_error(flag + " expects a non-negative integer, not " + quoted_excerpt(text));
  return static_cast<unsigned int>(v);
}

void set_number(double& value, bool& given, const std::string& flag, const std::string& text, bool zero_allowed,
                bool given_if_invalid)
{
  value = parse_double(flag, text);
  if(given_if_invalid) given = true;
  if(zero_allowed ? !(value >= 0) : !(value > 0))
    usage_error(flag + (zero_allowed ? " must be >= 0" : " must be positive"));
  given = true;
}

void set_number(std::optional<double>& value, const std::string& flag, const std::string& text, bool zero_allowed)
{
  double v = 0;
  bool given = false;
  set_number(v, given, flag, text, zero_allowed);
  value = v;
}

double parse_memory_size(const std::string& flag, const std::string& text)
{
  if(text == "off") return std::numeric_limits<double>::infinity();
  const std::string units = "KMGT";
  const std::size_t unit = text.empty() ? std::string::npos : units.find(char(std::toupper(text.back())));
  const std::string number = unit == std::string::npos ? text : text.substr(0, text.size() - 1);
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(number.c_str(), &end);
  if(number.empty() || end != number.c_str() + number.size() || !std::isfinite(v) || !(v >= 0))
    usage_error(flag + " expects a size such as 6G, 500M or 1048576 (bytes), or off, not " + quoted_excerpt(text));
  return unit == std::string::npos ? v : v * std::pow(1024.0, double(unit + 1));
}

std::size_t choice_index(const std::string& flag, const std::string& text, const std::vector<const char*>& names)
{
  for(std::size_t i = 0; i < names.size(); ++i)
    if(text == names[i]) return i;
  usage_error(flag + " expects " + word_list(names) + ", not " + quoted_excerpt(text));
}

bool same_file(const std::string& a, const std::string& b)
{
  std::error_code ec1, ec2;
  if(fs::exists(a, ec1) && fs::exists(b, ec2))
  {
    std::error_code ec;
    return fs::equivalent(a, b, ec);
  }
  return fs::weakly_canonical(a, ec1) == fs::weakly_canonical(b, ec2);
}

} // namespace af_tool
