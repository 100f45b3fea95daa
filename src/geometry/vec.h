#pragma once
/// \file
/// Eigen vocabulary of the project and the conversions to and from the C ABI.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "manifuzz/abi.h"

namespace mfz {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;
using Mat3 = Eigen::Matrix3d;

inline Vec3 to_vec(const mfz_vec3& v) { return {v.x, v.y, v.z}; }
inline mfz_vec3 to_abi(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline Quat to_quat(const mfz_quat& q) { return Quat(q.w, q.x, q.y, q.z); }
inline mfz_quat to_abi(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }

/// A rigid pose: world = rotation * local + position.
struct Pose {
  Vec3 position = Vec3::Zero();
  Quat orientation = Quat::Identity();

  Vec3 to_world(const Vec3& local) const { return orientation * local + position; }
  Vec3 rotate(const Vec3& local) const { return orientation * local; }
  Vec3 to_local_direction(const Vec3& world) const { return orientation.conjugate() * world; }
  mfz_pose to_abi() const { return {mfz::to_abi(position), mfz::to_abi(orientation)}; }
  static Pose from_abi(const mfz_pose& p) { return {to_vec(p.position), to_quat(p.orientation)}; }
};

}  // namespace mfz
