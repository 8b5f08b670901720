// anisotropic_fairing tool: the lines and numbers of a text mesh file, each read with its line number,
// so that every message can name the line (mesh_file_check.cpp, ply_file_check.cpp).

#ifndef AF_TOOL_TEXT_TOKENS_H
#define AF_TOOL_TEXT_TOKENS_H

#include "mesh_file_check.h"
#include "message_text.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace af_tool {

/// The file's text, line by line; `#` starts a comment (OFF, OBJ) unless `comments` is false (PLY).
class Text_lines
{
public:
  Text_lines(std::string_view text, std::string path, bool comments = true)
    : text_(text), path_(std::move(path)), comments_(comments) {}

  /// The tokens of the next line that has any; false at the end of the file.
  bool next(std::vector<std::string_view>& tokens)
  {
    tokens.clear();
    while(pos_ < text_.size() && tokens.empty())
    {
      std::size_t end = text_.find('\n', pos_);
      if(end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      if(comments_)
      {
        const std::size_t hash = line.find('#');
        if(hash != std::string_view::npos) line = line.substr(0, hash);
      }
      split(line, tokens);
    }
    return !tokens.empty();
  }

  std::size_t line() const { return line_; }
  std::size_t offset() const { return pos_ > text_.size() ? text_.size() : pos_; }
  const std::string& path() const { return path_; }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw File_problem(path_ + " line " + std::to_string(line_) + ": " + what);
  }

  /// A double, finite unless `finite` is false (nan and inf are then read as they are); fails naming
  /// `what` otherwise.
  double real(std::string_view t, const char* what, bool finite = true) const
  {
    double v = 0;
    if(!t.empty() && t.front() == '+') t.remove_prefix(1);
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if(r.ec == std::errc::result_out_of_range)
      fail(std::string(what) + " " + quoted_excerpt(t) + " is outside the range of double precision");
    if(r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(std::string(what) + " " + quoted_excerpt(t) + " is not a number");
    if(finite && !std::isfinite(v)) fail(std::string(what) + " " + quoted_excerpt(t) + " is not a finite number");
    return v;
  }

  /// An integer; fails naming `what` otherwise.
  long long integer(std::string_view t, const char* what) const
  {
    long long v = 0;
    if(!t.empty() && t.front() == '+') t.remove_prefix(1);
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if(r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(std::string(what) + " " + quoted_excerpt(t) + " is not an integer");
    return v;
  }

  static void split(std::string_view line, std::vector<std::string_view>& tokens)
  {
    std::size_t i = 0;
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
    while(i < line.size())
    {
      while(i < line.size() && blank(line[i])) ++i;
      const std::size_t start = i;
      while(i < line.size() && !blank(line[i])) ++i;
      if(i > start) tokens.push_back(line.substr(start, i - start));
    }
  }

private:
  std::string_view text_;
  std::string path_;
  bool comments_;
  std::size_t pos_ = 0, line_ = 0;
};

/// The whole file; fails if it cannot be read.
std::string file_contents(const std::string& path);

/// Throws File_problem for a count that `bytes` cannot hold at `each` bytes per item (checked before
/// anything is allocated for the items).
void check_count(const std::string& path, const std::string& what, unsigned long long count, const std::string& unit,
                 std::size_t bytes, std::size_t each);

/// Adds a face after checking its size and its indices against the vertex count.
void add_face(Polygon_soup& soup, const std::vector<long long>& index, std::size_t vertices, const std::string& place,
              const std::string& path);

/// The readers of each format, over the file's text (read_checked_soup() chooses).
Polygon_soup read_checked_off(const std::string& path, const std::string& text);
Polygon_soup read_checked_obj(const std::string& path, const std::string& text);
Polygon_soup read_checked_ply(const std::string& path, const std::string& text);
Polygon_soup read_checked_stl(const std::string& path, const std::string& text);

} // namespace af_tool

#endif // AF_TOOL_TEXT_TOKENS_H
