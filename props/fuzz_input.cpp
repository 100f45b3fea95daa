#include "fuzz_input.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace mfz::props {
namespace {

static_assert(std::endian::native == std::endian::little, "fuzz inputs are little-endian doubles");

constexpr size_t kHeader = 4;
constexpr size_t kPoseDoubles = 7;

class Reader {
 public:
  explicit Reader(const uint8_t* data) : data_(data) {}
  // False once a double is not finite: such an input is no case.
  bool next(double& out) {
    std::memcpy(&out, data_ + at_, sizeof out);
    at_ += sizeof out;
    return std::isfinite(out);
  }
  void skip_to(size_t at) { at_ = at; }

 private:
  const uint8_t* data_;
  size_t at_ = 0;
};

bool read_points(Reader& in, int count, std::vector<Vec3>& points) {
  points.resize(count);
  for (Vec3& p : points)
    for (int k = 0; k < 3; ++k)
      if (!in.next(p[k])) return false;
  return true;
}

bool read_pose(Reader& in, Pose& pose) {
  double v[kPoseDoubles];
  for (double& x : v)
    if (!in.next(x)) return false;
  pose.position = Vec3(v[0], v[1], v[2]);
  pose.orientation = Quat(v[3], v[4], v[5], v[6]);
  return true;
}

void put(std::vector<uint8_t>& out, double x) {
  uint8_t bytes[sizeof x];
  std::memcpy(bytes, &x, sizeof x);
  out.insert(out.end(), bytes, bytes + sizeof x);
}

void put_points(std::vector<uint8_t>& out, const std::vector<Vec3>& points, int count) {
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) put(out, points[i][k]);
}

void put_pose(std::vector<uint8_t>& out, const Pose& pose) {
  for (int k = 0; k < 3; ++k) put(out, pose.position[k]);
  const Quat& q = pose.orientation;
  for (double x : {q.w(), q.x(), q.y(), q.z()}) put(out, x);
}

}  // namespace

size_t fuzz_input_size(int points_a, int points_b) {
  return kHeader + sizeof(double) * (3 * (points_a + points_b) + 2 * kPoseDoubles);
}

std::optional<FuzzCase> decode_fuzz_input(const uint8_t* data, size_t size) {
  if (size < kHeader) return std::nullopt;
  const int count_a = data[2], count_b = data[3];
  for (int n : {count_a, count_b})
    if (n < 4 || n > kFuzzMaxPoints) return std::nullopt;
  if (size < fuzz_input_size(count_a, count_b)) return std::nullopt;
  FuzzCase c;
  c.family_a = data[0];
  c.family_b = data[1];
  Reader in(data);  // the size was checked above
  in.skip_to(kHeader);
  if (!read_points(in, count_a, c.file.points_a) || !read_points(in, count_b, c.file.points_b) ||
      !read_pose(in, c.file.pose_a) || !read_pose(in, c.file.pose_b))
    return std::nullopt;
  return c;
}

std::vector<uint8_t> encode_fuzz_input(const FuzzCase& c) {
  const int count_a = std::min<int>(kFuzzMaxPoints, static_cast<int>(c.file.points_a.size()));
  const int count_b = std::min<int>(kFuzzMaxPoints, static_cast<int>(c.file.points_b.size()));
  std::vector<uint8_t> out = {c.family_a, c.family_b, static_cast<uint8_t>(count_a), static_cast<uint8_t>(count_b)};
  out.reserve(fuzz_input_size(count_a, count_b));
  put_points(out, c.file.points_a, count_a);
  put_points(out, c.file.points_b, count_b);
  put_pose(out, c.file.pose_a);
  put_pose(out, c.file.pose_b);
  return out;
}

CaseParse read_case_or_fuzz_input(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {std::nullopt, quoted(path, 4096) + ": cannot be read"};
  std::string bytes;
  bytes.resize(kMaxCaseFileBytes + 1);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<size_t>(in.gcount()));
  if (bytes.rfind("manifuzz-case", 0) == 0 || bytes.rfind("#", 0) == 0) return read_case_file(path);
  const auto decoded = decode_fuzz_input(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  if (!decoded) return {std::nullopt, quoted(path, 4096) + ": neither a case file nor a fuzz input that holds a case"};
  return {decoded->file, {}};
}

}  // namespace mfz::props
