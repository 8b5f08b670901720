// Capturing what CGAL's readers and writers print, so that a failure stays a one-line message of the
// program (mesh_io.cpp, mesh_write.cpp).
#ifndef AF_TOOL_CAPTURED_STREAMS_H
#define AF_TOOL_CAPTURED_STREAMS_H

#include "message_text.h"

#include <iostream>
#include <sstream>
#include <string>

namespace af_tool {

class Capture_streams
{
public:
  Capture_streams() : cerr_(std::cerr.rdbuf(err_.rdbuf())), cout_(std::cout.rdbuf(out_.rdbuf())) {}
  ~Capture_streams() { std::cerr.rdbuf(cerr_); std::cout.rdbuf(cout_); }
  // the first non-empty line printed, if any
  std::string first_line() const
  {
    std::istringstream in(err_.str() + "\n" + out_.str());
    std::string line;
    while(std::getline(in, line))
      if(!one_line(line).empty()) return one_line(line);
    return std::string();
  }
private:
  std::ostringstream err_, out_;
  std::streambuf* cerr_;
  std::streambuf* cout_;
};

} // namespace af_tool

#endif // AF_TOOL_CAPTURED_STREAMS_H
