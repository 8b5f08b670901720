// --snapshot (see snapshot.h).
#include "snapshot.h"

#include "tool_common.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace af_tool {
namespace fs = std::filesystem;

std::string render_script()
{
  std::error_code ec;
  if(const char* env = std::getenv("AF_RENDER_SCRIPT")) return fs::exists(env, ec) ? std::string(env) : std::string();
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if(!ec)
  {
    const fs::path installed = exe.parent_path().parent_path() / "share" / "anisotropic_fairing" / "render_mesh.py";
    if(fs::exists(installed, ec)) return installed.string();
  }
  const fs::path source = AF_SOURCE_RENDER_SCRIPT;
  return fs::exists(source, ec) ? source.string() : std::string();
}

void render_snapshot(const std::string& script, const std::string& input, const std::string& result,
                     const std::string& input_title, const std::string& result_title, const std::string& png,
                     const std::string& name)
{
  std::string python = "python3";
  std::error_code ec;
  if(const char* env = std::getenv("AF_PYTHON")) python = env;
  else if(fs::exists("/usr/bin/python3", ec)) python = "/usr/bin/python3";

  // the renderer's messages go to a file, so that a failure is still one line of ours
  const fs::path log = fs::temp_directory_path(ec) / ("af_snapshot_" + std::to_string(long(::getpid())) + ".log");
  std::vector<std::string> args = { python,      script,    "--output",   png,   "--title",
                                    input_title, "--title", result_title, input, result };
  std::vector<char*> argv;
  for(std::string& a : args) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if(spawned == 0) waitpid(pid, &status, 0);
  std::string last;
  {
    std::ifstream in(log);
    for(std::string line; std::getline(in, line);)
      if(line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  fs::remove(log, ec);
  if(spawned != 0)
    fail("snapshot_error", "--snapshot: cannot run " + python + " (set AF_PYTHON to a Python 3 with VTK)");
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(png, ec))
    fail("snapshot_error",
         "--snapshot: rendering " + name + " failed" + (last.empty() ? std::string() : ": " + one_line(last)));
}

} // namespace af_tool
