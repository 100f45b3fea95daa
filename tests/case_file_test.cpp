#include "case/case_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

#include "test_support.h"

namespace mfz {
namespace {

constexpr const char* kValid =
    "manifuzz-case 1\n"
    "# a comment line\n"
    "hull A\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1   # trailing comment\n"
    "pose A  0 0 0  1 0 0 0\n"
    "hull B\n"
    "v 0x1p-1 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "pose B  0.5 0 0  2 0 0 0\n";

std::string parse_error(const std::string& text) {
  const CaseParse parsed = parse_case(text);
  EXPECT_FALSE(parsed.value) << "expected an error for:\n" << text;
  return parsed.error;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(CaseFileReading, ReadsPointsPosesAndHexFloats) {
  const CaseParse parsed = parse_case(kValid);
  ASSERT_TRUE(parsed.value) << parsed.error;
  EXPECT_EQ(parsed.value->points_a.size(), 4u);
  EXPECT_EQ(parsed.value->points_b[0].x(), 0.5);
  EXPECT_EQ(parsed.value->pose_b.position.x(), 0.5);
  EXPECT_EQ(parsed.value->pose_b.orientation.w(), 2.0) << "the reader keeps the quaternion as written";
}

TEST(CaseFileReading, KeepsExtensionLinesAndAcceptsCrLf) {
  std::string text = std::string(kValid) + "note found by the fuzzer\r\nexpect-depth 0.5\n";
  const CaseParse parsed = parse_case(text);
  ASSERT_TRUE(parsed.value) << parsed.error;
  ASSERT_EQ(parsed.value->extensions.size(), 2u);
  EXPECT_EQ(parsed.value->extensions[0], "note found by the fuzzer");
}

TEST(CaseFileReading, ErrorsNameTheLine) {
  EXPECT_EQ(parse_error("hull A\n"), "line 1: expected the header 'manifuzz-case 1'");
  EXPECT_EQ(parse_error("manifuzz-case 2\n"), "line 1: unsupported case file version '2' (this reader knows 1)");
  EXPECT_EQ(parse_error("manifuzz-case 1\nv 1 2 3\n"), "line 2: a vertex 'v' before 'hull A' or 'hull B'");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\nv 1 2\n"), "line 3: expected 3 numbers after 'v', found 2");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\nv 1 2 x\n"), "line 3: 'x' is not a number");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull C\n"), "line 2: expected 'hull A' or 'hull B'");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\n1 2 3\n"), "line 3: unrecognised line starting with '1'");
}

TEST(CaseFileReading, NanAndInfAreErrors) {
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\nv nan 0 0\n"),
            "line 3: 'nan' is not finite (NaN and Inf are not allowed)");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\nv 0 0 0\npose A 0 0 inf 1 0 0 0\n"),
            "line 4: 'inf' is not finite (NaN and Inf are not allowed)");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\nv 0 0 1e999\n"),
            "line 3: '1e999' is not finite (NaN and Inf are not allowed)");
}

TEST(CaseFileReading, MissingSectionsAndZeroQuaternionAreErrors) {
  EXPECT_EQ(parse_error(""), "line 1: empty file: expected the header 'manifuzz-case 1'");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\nv 0 0 0\npose A 0 0 0 1 0 0 0\n"), "line 5: no 'hull B' section");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\npose A 0 0 0 0 0 0 0\n"),
            "line 3: the orientation quaternion is zero");
  EXPECT_EQ(parse_error("manifuzz-case 1\nhull A\nhull A\n"), "line 3: hull A appears twice");
}

TEST(CaseFileWriting, NumbersReadBackToTheSameBits) {
  std::mt19937_64 random(0x1ee7c0de);
  CaseFile c;
  const auto any_double = [&] {
    double d;
    do {
      const uint64_t bits = random();
      std::memcpy(&d, &bits, sizeof d);
    } while (!std::isfinite(d));
    return d;
  };
  for (int k = 0; k < 200; ++k) c.points_a.emplace_back(any_double(), any_double(), any_double());
  c.points_b = {{-0.0, 5e-324, std::numeric_limits<double>::max()}, {0.1, 1.0 / 3, -2.5e-300}};
  c.pose_a = {Vec3(any_double(), 1e6 + 0.1, -0.0), Quat(0.1, 0.2, 0.3, 0.4)};
  c.pose_b = {Vec3(1, 2, 3), Quat(1, 0, 0, 0)};
  c.extensions = {"note round trip"};
  const CaseParse back = parse_case(format_case(c));
  ASSERT_TRUE(back.value) << back.error;
  ASSERT_EQ(back.value->points_a.size(), c.points_a.size());
  for (size_t i = 0; i < c.points_a.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(back.value->points_a[i][k], c.points_a[i][k]));
  for (size_t i = 0; i < c.points_b.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(back.value->points_b[i][k], c.points_b[i][k]));
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(same_bits(back.value->pose_a.position[k], c.pose_a.position[k]));
  EXPECT_TRUE(same_bits(back.value->pose_a.orientation.z(), 0.4));
  EXPECT_EQ(back.value->extensions, c.extensions);
  EXPECT_EQ(format_case(*back.value), format_case(c));
}

}  // namespace
// A full disk (here a file-size limit) fails the write, says so, and leaves
// the case already there as it was: never an empty or half-written file.
TEST(CaseFileWriting, AFailedWriteReportsItAndKeepsTheOldFile) {
  const std::string path = ::testing::TempDir() + "/kept.case";
  CaseFile small = test::make_case(test::tetrahedron_points(), {}, test::tetrahedron_points(), {});
  std::string error;
  ASSERT_TRUE(write_case_file(path, small, error)) << error;
  const std::string before = format_case(small);
  CaseFile large = small;
  for (int i = 0; i < 200; ++i) large.extensions.push_back("note padding line " + std::to_string(i));
  rlimit old{};
  getrlimit(RLIMIT_FSIZE, &old);
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  rlimit tight = old;
  tight.rlim_cur = 512;
  setrlimit(RLIMIT_FSIZE, &tight);
  const bool written = write_case_file(path, large, error);
  setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  EXPECT_FALSE(written);
  EXPECT_NE(error.find("write failed"), std::string::npos) << error;
  const CaseParse reread = read_case_file(path);
  ASSERT_TRUE(reread.value) << reread.error;
  EXPECT_EQ(format_case(*reread.value), before);
  for (const auto& entry : std::filesystem::directory_iterator(::testing::TempDir()))
    EXPECT_EQ(entry.path().string().find("kept.case.tmp"), std::string::npos) << "a temporary file was left behind";
}

TEST(CaseFileReading, RefusesANulInsideANumberAndEscapesControlBytes) {
  using namespace std::string_literals;
  const CaseParse nul = parse_case("manifuzz-case 1\nhull A\nv 1\0" "9 0 0\n"s);
  ASSERT_FALSE(nul.value);
  EXPECT_NE(nul.error.find("line 3"), std::string::npos) << nul.error;
  EXPECT_NE(nul.error.find("\\x00"), std::string::npos) << nul.error;
  const CaseParse escape = parse_case("manifuzz-case 1\n\x1b[31mred\n");
  ASSERT_FALSE(escape.value);
  EXPECT_EQ(escape.error.find('\x1b'), std::string::npos) << "a raw escape byte reached the message";
}

}  // namespace mfz
