// Reading /proc while the fuzzing engine's processes come and go: a process
// that ends between the open and the read is a read error, not an exception.
#include <gtest/gtest.h>

#include <csignal>
#include <string>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "process_memory.h"

namespace mfz::props {
namespace {

TEST(ProcessMemory, AStatFileWhoseProcessEndedReadsAsAnErrorWithoutThrowing) {
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    pause();
    _exit(0);
  }
  const std::string path = "/proc/" + std::to_string(child) + "/stat";
  const int fd = open(path.c_str(), O_RDONLY);
  ASSERT_GE(fd, 0);
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  std::optional<std::string> text;
  EXPECT_NO_THROW(text = read_to_end(fd));
  EXPECT_FALSE(text.has_value());
  close(fd);
}

TEST(ProcessMemory, OwnGroupHoldsSomeMemory) {
  EXPECT_GT(group_resident_mb(getpgrp()), 0.0);
  EXPECT_EQ(group_resident_mb(999999999), 0.0);
}

}  // namespace
}  // namespace mfz::props
