// Units of a scene (scene.h) and the SI -> dimensionless conversions (scene_units.h).
#include "scene/scene_units.h"

#include <cctype>
#include <cmath>
#include <cstdio>

namespace cb {

double Units::omega0() const {
  return std::sqrt(stiffness / mass);
}

double Units::force_scale() const {
  return stiffness * length;
}

// gamma = Gamma / (2 m omega0), below Eq. (dimless).
double Units::gamma() const {
  return friction / (2.0 * mass * omega0());
}

namespace scene_detail {

Conversion conversion_for(const std::optional<Units>& units) {
  Conversion c;
  if (units && units->si_input) {
    c.si = true;
    c.omega0 = units->omega0();
    c.force_scale = units->force_scale();
  }
  return c;
}

namespace {

// 17 significant digits: the rewritten expression evaluates to the same double as the
// conversion would, so SI and dimensionless scenes agree to rounding.
std::string exact_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

bool ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

}  // namespace

std::string expr_to_dimensionless(const std::string& expr, const Conversion& c) {
  const std::string t_seconds = "(t/" + exact_text(c.omega0) + ")";
  std::string out;
  for (std::size_t i = 0; i < expr.size();) {
    if (std::isdigit(static_cast<unsigned char>(expr[i])) || expr[i] == '.') {
      // A number, exponent included ("1e-3"), so its letters are never taken for names.
      std::size_t j = i;
      while (j < expr.size() &&
             (std::isalnum(static_cast<unsigned char>(expr[j])) || expr[j] == '.' ||
              ((expr[j] == '+' || expr[j] == '-') && (expr[j - 1] == 'e' || expr[j - 1] == 'E'))))
        ++j;
      out.append(expr, i, j - i);
      i = j;
    } else if (ident_start(expr[i])) {
      std::size_t j = i;
      while (j < expr.size() && ident_char(expr[j])) ++j;
      const std::string name = expr.substr(i, j - i);
      out += name == "t" ? t_seconds : name;
      i = j;
    } else {
      out += expr[i++];
    }
  }
  return "(" + out + ")/" + exact_text(c.force_scale);
}

}  // namespace scene_detail
}  // namespace cb
