#pragma once

#include <cmath>

namespace fooball {

/// A 2-D vector in SI units (metres, m/s, newtons, … as the context says).
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr Vec2& operator*=(double s) {
    x *= s;
    y *= s;
    return *this;
  }
  friend constexpr bool operator==(Vec2, Vec2) = default;
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
constexpr Vec2 operator-(Vec2 a) {
  return {-a.x, -a.y};
}
constexpr Vec2 operator*(double s, Vec2 v) {
  return {s * v.x, s * v.y};
}
constexpr Vec2 operator*(Vec2 v, double s) {
  return {s * v.x, s * v.y};
}
constexpr Vec2 operator/(Vec2 v, double s) {
  return {v.x / s, v.y / s};
}

constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
constexpr double lengthSquared(Vec2 v) {
  return dot(v, v);
}
inline double length(Vec2 v) {
  return std::hypot(v.x, v.y);
}
inline bool isFinite(Vec2 v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

}  // namespace fooball
