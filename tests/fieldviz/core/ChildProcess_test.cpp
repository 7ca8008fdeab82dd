// runChildProcess against what /bin/sh is told to do: its stdout whole and in order, its stderr,
// its exit code or signal; a program that does not exist is an error naming it.
#include "fieldviz/core/ChildProcess.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace fluidviz;

namespace {

ChildProcessResult shell(const std::string& script, std::string& out) {
  return runChildProcess({"/bin/sh", "-c", script}, [&](std::string_view piece) { out.append(piece); });
}

}  // namespace

TEST(ChildProcess, HandsOverStdoutAndStderrAndTheExitCode) {
  std::string out;
  const ChildProcessResult r = shell("printf 'one\\ntwo'; printf 'complaint' >&2; exit 3", out);
  EXPECT_EQ(out, "one\ntwo");
  EXPECT_EQ(r.errors, "complaint");
  EXPECT_FALSE(exitedWithZero(r.status));
  EXPECT_EQ(exitDescription(r.status), "exit code 3");
}

// 1 MiB, more than a pipe holds (64 KiB): the child blocks until the parent reads, so this
// also checks that reading and waiting come in that order.
TEST(ChildProcess, OutputLargerThanAPipeArrivesWhole) {
  std::string out;
  const ChildProcessResult r = shell("head -c 1048576 /dev/zero", out);
  EXPECT_TRUE(exitedWithZero(r.status)) << exitDescription(r.status) << r.errors;
  EXPECT_EQ(out.size(), 1048576u);
  EXPECT_EQ(out.find_first_not_of('\0'), std::string::npos);
}

TEST(ChildProcess, SignalsAreNamedAndStdinIsEmpty) {
  std::string out;
  EXPECT_EQ(exitDescription(shell("kill -9 $$", out).status), "signal 9");
  const ChildProcessResult r = shell("wc -c", out);
  EXPECT_TRUE(exitedWithZero(r.status));
  EXPECT_EQ(std::stoi(out), 0) << "stdin comes from /dev/null";
}

TEST(ChildProcess, AMissingProgramIsAnErrorNamingIt) {
  try {
    runChildProcess({"/nonexistent/fluidviz-helper"}, [](std::string_view) {});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot start /nonexistent/fluidviz-helper: No such file"),
              std::string::npos)
        << e.what();
  }
}
