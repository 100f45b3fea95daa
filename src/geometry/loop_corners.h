#pragma once
/// \file
/// The corners either side of corner k of a loop of n corners, without a
/// division: `(k + 1) % n` is an integer division, tens of cycles, and a
/// box call made about forty of them in its clip, its side planes and its
/// contacts' closest points.
namespace mfz {

/// The corner after k (k in 0..n-1).
inline int next_corner(int k, int n) { return k + 1 < n ? k + 1 : 0; }
/// The corner before k (k in 0..n-1).
inline int previous_corner(int k, int n) { return k > 0 ? k - 1 : n - 1; }

}  // namespace mfz
