#include "solvers/lbm/LbmParams.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

namespace fluidviz::lbm {

namespace {

std::string formatNumber(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

// Checks each member against its declared ParamInfo (range, choices), so that a solver built
// directly from code is held to the same rules as one built from a scene file.
class DeclaredRangeCheck {
 public:
  explicit DeclaredRangeCheck(std::string prefix) : prefix_(std::move(prefix)) {}

  template <class S>
  static void run(const S& s, const std::string& prefix) {
    DeclaredRangeCheck check(prefix);
    check.object_ = &s;
    S::describe(check);
  }

  template <class C, class T>
  void operator()(T C::*member, const ParamInfo& info) {
    const T& value = static_cast<const C*>(object_)->*member;
    checkValue(value, prefix_ + info.key, info);
  }

 private:
  static void checkValue(double v, const std::string& key, const ParamInfo& info) {
    const bool below = info.minExclusive ? !(v > info.min) : !(v >= info.min);
    if (!std::isfinite(v) || below || v > info.max)
      throw ParamError(key, "is " + formatNumber(v) + "; allowed " + describeRange(info));
  }
  static void checkValue(int v, const std::string& key, const ParamInfo& info) {
    checkValue(static_cast<double>(v), key, info);
  }
  static void checkValue(const std::optional<double>& v, const std::string& key,
                         const ParamInfo& info) {
    if (v) checkValue(*v, key, info);
  }
  template <std::size_t N>
  static void checkValue(const std::array<double, N>& v, const std::string& key,
                         const ParamInfo& info) {
    for (std::size_t i = 0; i < N; ++i) checkValue(v[i], key + "[" + std::to_string(i) + "]", info);
  }
  static void checkValue(const std::string& v, const std::string& key, const ParamInfo& info) {
    if (!info.choices.empty() &&
        std::find(info.choices.begin(), info.choices.end(), v) == info.choices.end())
      throw ParamError(key, "is \"" + v + "\"; allowed " + describeRange(info));
  }
  template <class T>
  static void checkValue(const std::vector<T>& v, const std::string& key, const ParamInfo&) {
    for (std::size_t i = 0; i < v.size(); ++i)
      run(v[i], key + "[" + std::to_string(i) + "].");
  }
  template <class T>
    requires std::is_class_v<T>
  static void checkValue(const T& v, const std::string& key, const ParamInfo&) {
    run(v, key + ".");
  }

  std::string prefix_;
  const void* object_ = nullptr;
};

void checkViscosityOrReynolds(const LbmParams& p) {
  if (p.viscosity && p.reynolds)
    throw ParamError("viscosity",
                     "and lbm.reynolds are both given; give exactly one of them (the other "
                     "follows from Re = U_ref L_ref / nu)");
  if (!p.viscosity && !p.reynolds)
    throw ParamError("viscosity",
                     "is missing: give exactly one of lbm.viscosity (m^2/s) or lbm.reynolds");
}

void checkPeriodicPairs(const WallsParams& w) {
  auto pair = [](const WallParams& lo, const WallParams& hi, const std::string& loKey,
                 const std::string& hiKey) {
    const bool a = lo.type == "periodic", b = hi.type == "periodic";
    if (a != b)
      throw ParamError(a ? "walls." + hiKey + ".type" : "walls." + loKey + ".type",
                       "is \"" + (a ? hi.type : lo.type) + "\" but walls." + (a ? loKey : hiKey) +
                           " is periodic; periodic sides come in pairs: make both walls." +
                           loKey + " and walls." + hiKey + " periodic, or neither");
  };
  pair(w.x_min, w.x_max, "x_min", "x_max");
  pair(w.y_min, w.y_max, "y_min", "y_max");
}

// normalAxis: 0 for the x sides (normal along x), 1 for the y sides.
void checkWallVelocity(const WallParams& w, const std::string& key, int normalAxis) {
  const bool moving = w.type == "moving_wall";
  const bool hasVelocity = w.velocity[0] != 0.0 || w.velocity[1] != 0.0;
  if (!moving && hasVelocity)
    throw ParamError("walls." + key + ".velocity",
                     "is non-zero but walls." + key + ".type is \"" + w.type +
                         "\"; set the type to moving_wall or the velocity to [0, 0]");
  if (moving && w.velocity[normalAxis] != 0.0)
    throw ParamError("walls." + key + ".velocity",
                     std::string("has a component normal to the wall (") +
                         (normalAxis == 0 ? "x" : "y") + " = " +
                         formatNumber(w.velocity[normalAxis]) +
                         " m/s); a wall can only slide along itself: set it to 0");
}

void checkRollers(const LbmParams& p) {
  const double lx = p.domain_size[0], ly = p.domain_size[1];
  for (std::size_t i = 0; i < p.rollers.size(); ++i) {
    const RollerParams& r = p.rollers[i];
    const std::string key = "rollers[" + std::to_string(i) + "]";
    const double x = r.center[0], y = r.center[1];
    if (x - r.radius < 0 || x + r.radius > lx || y - r.radius < 0 || y + r.radius > ly)
      throw ParamError(key, "(centre [" + formatNumber(x) + ", " + formatNumber(y) +
                                "] m, radius " + formatNumber(r.radius) +
                                " m) does not lie inside the box [0, " + formatNumber(lx) +
                                "] x [0, " + formatNumber(ly) +
                                "] m; move its centre or reduce its radius");
    for (std::size_t k = 0; k < i; ++k) {
      const RollerParams& o = p.rollers[k];
      if (std::hypot(x - o.center[0], y - o.center[1]) < r.radius + o.radius)
        throw ParamError(key, "overlaps rollers[" + std::to_string(k) +
                                  "]; move the centres apart or reduce the radii");
    }
  }
}

}  // namespace

void validateLbmParams(const LbmParams& p) {
  DeclaredRangeCheck::run(p, "");
  checkViscosityOrReynolds(p);
  checkPeriodicPairs(p.walls);
  checkWallVelocity(p.walls.x_min, "x_min", 0);
  checkWallVelocity(p.walls.x_max, "x_max", 0);
  checkWallVelocity(p.walls.y_min, "y_min", 1);
  checkWallVelocity(p.walls.y_max, "y_max", 1);
  checkRollers(p);
}

double referenceVelocity(const LbmParams& p) {
  double u = 0.0;
  for (const WallParams* w : {&p.walls.x_min, &p.walls.x_max, &p.walls.y_min, &p.walls.y_max})
    if (w->type == "moving_wall") u = std::max(u, std::hypot(w->velocity[0], w->velocity[1]));
  for (const RollerParams& r : p.rollers) u = std::max(u, std::abs(r.angular_velocity) * r.radius);
  return u;
}

}  // namespace fluidviz::lbm
