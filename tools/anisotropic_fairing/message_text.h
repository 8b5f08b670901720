// Text from files and command lines put into the program's one-line messages: a file may hold any
// bytes, and a message must stay one printable line on the terminal.
#ifndef AF_TOOL_MESSAGE_TEXT_H
#define AF_TOOL_MESSAGE_TEXT_H

#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

namespace af_tool {

// The length of the valid UTF-8 sequence of more than one byte at s[i], or 0.
inline std::size_t utf8_sequence(std::string_view s, std::size_t i)
{
  const unsigned char c = static_cast<unsigned char>(s[i]);
  const std::size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if(n == 0 || i + n > s.size()) return 0;
  for(std::size_t k = 1; k < n; ++k)
    if((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  return n;
}

// `s` with every control character and every byte that is not part of valid UTF-8 written as \xNN
// (a backslash as \\ only when `escape_backslash`), so that it prints as one line.
inline std::string printable(std::string_view s, bool escape_backslash = false)
{
  std::string out;
  for(std::size_t i = 0; i < s.size();)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if(c >= 0x80)
    {
      if(const std::size_t n = utf8_sequence(s, i)) { out.append(s.substr(i, n)); i += n; continue; }
    }
    else if(c >= 0x20 && c != 0x7F)
    {
      if(c == '\\' && escape_backslash) out += '\\';
      out += char(c);
      ++i;
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02X", unsigned(c));
    out += hex;
    ++i;
  }
  return out;
}

// A token of the input quoted for a message: at most `most` bytes of it, escaped, "..." if cut.
inline std::string quoted_excerpt(std::string_view token, std::size_t most = 32)
{
  const bool cut = token.size() > most;
  return "'" + printable(token.substr(0, most), true) + (cut ? "...'" : "'");
}

// The message on one printable line (the failure contract: one line on stderr): line breaks and tabs
// become blanks, other control characters and broken UTF-8 are escaped, trailing blanks dropped.
inline std::string one_line(std::string s)
{
  for(char& c : s)
    if(c == '\n' || c == '\r' || c == '\t') c = ' ';
  s = printable(s);
  while(!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

/// ": " and the system's reason for the error number `err` (strerror: "No space left on device", "Permission
/// denied", ...), or nothing when there is none (0)
inline std::string system_reason(int err)
{
  return err != 0 ? ": " + std::string(std::strerror(err)) : std::string();
}

} // namespace af_tool

#endif // AF_TOOL_MESSAGE_TEXT_H
