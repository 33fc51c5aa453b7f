#pragma once
/// @file
/// A point or vector of the plane (m, m/s, m/s²): the one type the geometry speaks.
#include <cmath>

namespace soilsph::sph {

struct Vec2 {
  double x = 0.0, y = 0.0;
  friend bool operator==(const Vec2&, const Vec2&) = default;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// z component of a × b: > 0 when b turns left from a.
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }

}  // namespace soilsph::sph
