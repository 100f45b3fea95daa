/// \file
/// The generator plugin ABI, version 1 (docs/contract.md, "The generator plugin ABI").
/// Plain C so that a generator written in any language can be loaded with dlopen.
/// Every length is in the caller's units; every pose maps local to world as
/// `world = R(orientation) * local + position`.
#ifndef MANIFUZZ_ABI_H
#define MANIFUZZ_ABI_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/// The ABI version this header describes; `mfz_abi_version()` must return it.
#define MFZ_ABI_VERSION 1
/// Capacity of `mfz_manifold::contacts`.
#define MFZ_MAX_CONTACTS 64

typedef struct mfz_vec3 { double x, y, z; } mfz_vec3;
/// Unit quaternion (w, x, y, z); the harness normalises it before a call.
typedef struct mfz_quat { double w, x, y, z; } mfz_quat;
typedef struct mfz_pose { mfz_vec3 position; mfz_quat orientation; } mfz_pose;

/// A convex polyhedron in local space. Face f's loop is
/// `face_vertices[face_offsets[f] .. face_offsets[f+1])`, counter-clockwise seen
/// from outside; `face_normals[f]` is its outward unit normal. Every edge is
/// shared by exactly two faces.
typedef struct mfz_hull {
  int32_t vertex_count;
  const mfz_vec3* vertices;
  int32_t face_count;
  const int32_t* face_offsets;   ///< face_count + 1 entries
  const int32_t* face_vertices;
  const mfz_vec3* face_normals;
} mfz_hull;

/// One contact: `point_on_b = point_on_a + penetration * manifold.normal`.
typedef struct mfz_contact {
  mfz_vec3 point_on_a;  ///< world space, on A's surface
  mfz_vec3 point_on_b;  ///< world space, on B's surface
  double penetration;   ///< < 0 for a contact that overlaps
} mfz_contact;

typedef struct mfz_manifold {
  int32_t colliding;     ///< 1 when no separating axis exists, else 0
  mfz_vec3 normal;       ///< unit, world space, from A towards B
  double penetration;    ///< -depth, <= 0
  int32_t contact_count; ///< 0 .. MFZ_MAX_CONTACTS
  mfz_contact contacts[MFZ_MAX_CONTACTS];
} mfz_manifold;

typedef int32_t (*mfz_abi_version_fn)(void);
typedef const char* (*mfz_generator_name_fn)(void);
/// Returns 0 on success; non-zero means the generator refused the input.
typedef int32_t (*mfz_generate_fn)(const mfz_hull* a, const mfz_pose* pose_a,
                                   const mfz_hull* b, const mfz_pose* pose_b,
                                   mfz_manifold* out);
/// Optional: what the generator promises, as space-separated key=value pairs
/// (precision=float max-contacts=4 face-bias=0.05 margin=0.01); the harness
/// relaxes exactly what each key names. Absent: the contract in full.
typedef const char* (*mfz_generator_profile_fn)(void);

#ifdef __cplusplus
}
#endif

#endif
