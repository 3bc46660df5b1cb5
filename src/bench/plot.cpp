#include "bench/plot.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "base/atomic_file.hpp"
#include "base/data_dir.hpp"

namespace tp::app {

void plotCsv(const std::string& script, const std::string& csv, const std::string& png) {
  const std::string path = (base::dataDir("tools", TIDEPOOL_TOOLS_DIR) / script).string();
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "warning: no plot: %s not found\n", path.c_str());
    return;
  }
  base::AtomicFile file(png);
  // Debian's python3-matplotlib belongs to /usr/bin/python3, which another
  // python3 earlier on PATH (pyenv, a venv) may hide.
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " '" + path + "' '" + csv + "' '" + file.tempPath() + "'";
  if (std::system(command.c_str()) != 0 || !std::filesystem::exists(file.tempPath())) {
    std::fprintf(stderr, "warning: no plot: %s failed (is python3-matplotlib installed?)\n", script.c_str());
    return;
  }
  file.commit();
  std::printf("wrote %s\n", png.c_str());
}

}  // namespace tp::app
