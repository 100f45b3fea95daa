#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "fuzz_input.h"
#include "test_support.h"

namespace mfz::props {
namespace {

FuzzCase box_pair() {
  FuzzCase c;
  c.file.points_a = test::box_points(1, 1, 1);
  c.file.points_b = test::box_points(0.5, 0.5, 0.5);
  c.file.pose_b = {Vec3(0, 0, 1.4), Quat(0.5, 0.5, 0.5, 0.5)};
  c.family_a = 3;
  c.family_b = 7;
  return c;
}

TEST(FuzzInput, DecodesWhatWasEncodedBitForBit) {
  FuzzCase c = box_pair();
  c.file.points_a[0].x() = -0.0;
  c.file.points_a[1].y() = std::numeric_limits<double>::denorm_min();
  c.file.points_b[2].z() = std::nextafter(1.0, 2.0);
  const std::vector<uint8_t> bytes = encode_fuzz_input(c);
  EXPECT_EQ(bytes.size(), fuzz_input_size(8, 8));
  const auto back = decode_fuzz_input(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(format_case(back->file), format_case(c.file));
  EXPECT_TRUE(std::signbit(back->file.points_a[0].x()));
  EXPECT_EQ(back->family_a, 3);
  EXPECT_EQ(back->family_b, 7);
}

TEST(FuzzInput, IgnoresBytesPastTheCase) {
  std::vector<uint8_t> bytes = encode_fuzz_input(box_pair());
  bytes.insert(bytes.end(), {1, 2, 3});
  EXPECT_TRUE(decode_fuzz_input(bytes.data(), bytes.size()));
}

TEST(FuzzInput, AShortInputACountOutOfRangeOrANanIsNoCase) {
  const std::vector<uint8_t> bytes = encode_fuzz_input(box_pair());
  EXPECT_FALSE(decode_fuzz_input(bytes.data(), bytes.size() - 1));
  EXPECT_FALSE(decode_fuzz_input(bytes.data(), 3));
  std::vector<uint8_t> three_points = bytes;
  three_points[2] = 3;
  EXPECT_FALSE(decode_fuzz_input(three_points.data(), three_points.size()));
  std::vector<uint8_t> too_many = bytes;
  too_many[3] = kFuzzMaxPoints + 1;
  EXPECT_FALSE(decode_fuzz_input(too_many.data(), too_many.size()));
  std::vector<uint8_t> with_nan = bytes;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::memcpy(with_nan.data() + 4, &nan, sizeof nan);
  EXPECT_FALSE(decode_fuzz_input(with_nan.data(), with_nan.size()));
}

TEST(FuzzInput, ACaseFileOrARawArtefactReadsAsACase) {
  const std::string raw = test::scratch_path("fuzz_input_raw");
  const std::vector<uint8_t> bytes = encode_fuzz_input(box_pair());
  std::FILE* f = std::fopen(raw.c_str(), "wb");
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  const CaseParse from_raw = read_case_or_fuzz_input(raw);
  ASSERT_TRUE(from_raw.value) << from_raw.error;
  EXPECT_EQ(format_case(*from_raw.value), format_case(box_pair().file));
  const CaseParse from_text = read_case_or_fuzz_input(test::corpus_path("box_on_box.case"));
  EXPECT_TRUE(from_text.value) << from_text.error;
  f = std::fopen(raw.c_str(), "wb");
  std::fputs("garbage", f);
  std::fclose(f);
  EXPECT_FALSE(read_case_or_fuzz_input(raw).value);
}

}  // namespace
}  // namespace mfz::props
