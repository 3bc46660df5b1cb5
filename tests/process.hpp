#pragma once
// Runs the tidepool executable as a user would, capturing its exit code,
// standard output and standard error, in a scratch directory per test.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace tp::test {

struct ProcessResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

inline std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh empty directory named after the running test, removed at the end.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("tidepool-" + std::string(info->test_suite_name()) + "-" + info->name() + "-" + std::to_string(getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  // Names of every entry in the directory (to prove nothing was left behind).
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path path_;
};

// `env`: put before the executable, e.g. "DISPLAY=:3" or "env -u DISPLAY".
inline ProcessResult runTidepool(const std::string& args, const ScratchDir& dir, const std::string& env = "") {
  const std::string out = dir.file("stdout.txt"), err = dir.file("stderr.txt");
  const std::string command = env + (env.empty() ? "" : " ") + std::string(TIDEPOOL_EXE) + " " + args + " >" + out +
                              " 2>" + err + " </dev/null";
  int status = std::system(command.c_str());
  ProcessResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = readText(out);
  r.err = readText(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

inline int lineCount(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  if (!text.empty() && text.back() != '\n') ++n;
  return n;
}

// Runs a command that must fail cleanly (one line on stderr starting
// "tidepool: error: ", an exit code that is neither 0 nor a crash, and the
// scratch directory left as it was) and returns what it gave.
inline ProcessResult cleanFailure(const std::string& args, const ScratchDir& dir,
                                  const std::vector<std::string>& filesBefore, const std::string& env = "") {
  ProcessResult r = runTidepool(args, dir, env);
  EXPECT_NE(r.exitCode, 0) << args;
  EXPECT_LT(r.exitCode, 128) << "crashed: " << args;
  EXPECT_EQ(lineCount(r.err), 1) << args << "\nstderr:\n" << r.err;
  EXPECT_EQ(r.err.rfind("tidepool: error: ", 0), 0u) << r.err;
  auto after = dir.entries();
  std::sort(after.begin(), after.end());
  auto before = filesBefore;
  std::sort(before.begin(), before.end());
  EXPECT_EQ(after, before) << "files left behind by: " << args;
  return r;
}

// As cleanFailure; returns the line.
inline std::string expectCleanFailure(const std::string& args, const ScratchDir& dir,
                                      const std::vector<std::string>& filesBefore, const std::string& env = "") {
  return cleanFailure(args, dir, filesBefore, env).err;
}

// A bad command line: as expectCleanFailure, with exit code 2.
inline std::string expectUsageError(const std::string& args, const ScratchDir& dir,
                                    const std::vector<std::string>& filesBefore = {}) {
  const ProcessResult r = cleanFailure(args, dir, filesBefore);
  EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
  return r.err;
}

inline void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Starts `tidepool args` in the background, waits (at most two minutes) for
// the file `waitFor` to appear, sends it `signal` and waits for it to end:
// a run stopped in the middle, as Ctrl-C or a farm's requeue stops it.
inline ProcessResult runUntilSignalled(const std::string& args, const ScratchDir& dir, const std::string& waitFor,
                                       int signal) {
  const std::string command = std::string(TIDEPOOL_EXE) + " " + args + " >" + dir.file("out.txt") + " 2>" +
                              dir.file("err.txt") + " </dev/null & p=$!; echo $p >" + dir.file("pid.txt") +
                              "; wait $p; echo $? >" + dir.file("rc.txt");
  std::thread run([&] { std::system(("bash -c '" + command + "'").c_str()); });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!std::filesystem::exists(waitFor) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  kill(std::stoi(readText(dir.file("pid.txt"))), signal);
  run.join();
  ProcessResult r;
  r.exitCode = std::stoi(readText(dir.file("rc.txt")));
  r.out = readText(dir.file("out.txt"));
  r.err = readText(dir.file("err.txt"));
  for (const char* name : {"out.txt", "err.txt", "pid.txt", "rc.txt"}) std::filesystem::remove(dir.file(name));
  return r;
}

}  // namespace tp::test
