#include "drive/drive.h"

#include <muParser.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>

namespace cb {

const char* drive_type_name(DriveType type) {
  switch (type) {
    case DriveType::Step:
      return "step";
    case DriveType::Ramp:
      return "ramp";
    case DriveType::Sine:
      return "sine";
    case DriveType::Impulses:
      return "impulses";
    case DriveType::Table:
      return "table";
    case DriveType::Expr:
      return "expr";
  }
  return "?";
}

bool parse_drive_type(const std::string& name, DriveType& out) {
  for (DriveType t : {DriveType::Step, DriveType::Ramp, DriveType::Sine, DriveType::Impulses,
                      DriveType::Table, DriveType::Expr}) {
    if (name == drive_type_name(t)) {
      out = t;
      return true;
    }
  }
  return false;
}

namespace {

// Piecewise-linear interpolation; constant beyond the last point, 0 before t0.
double table_value(const std::vector<std::pair<double, double>>& table, double t) {
  if (table.empty()) return 0.0;
  if (t <= table.front().first) return table.front().second;
  if (t >= table.back().first) return table.back().second;
  auto hi = std::upper_bound(table.begin(), table.end(), t,
                             [](double v, const auto& p) { return v < p.first; });
  auto lo = hi - 1;
  const double w = (t - lo->first) / (hi->first - lo->first);
  return lo->second + w * (hi->second - lo->second);
}

}  // namespace

double drive_value(const DriveDesc& d, double tau) {
  const double t = tau - d.t0;
  if (t < 0.0) return 0.0;
  switch (d.type) {
    case DriveType::Step:
      return d.amplitude;
    case DriveType::Ramp:
      return d.beta * t;
    case DriveType::Sine:
      return d.amplitude * std::sin(2.0 * std::numbers::pi * t / d.period);
    case DriveType::Table:
      return table_value(d.table, t);
    case DriveType::Impulses:
    case DriveType::Expr:
      return 0.0;
  }
  return 0.0;
}

namespace {

// muParser keeps a pointer to the variable, so parser and variable live together.
struct ExprFunction {
  mu::Parser parser;
  double t = 0.0;
};

}  // namespace

Forcing make_forcing(const DriveDesc& d) {
  Forcing forcing;
  switch (d.type) {
    case DriveType::Step:
      forcing.breakpoints = {d.t0};
      break;
    case DriveType::Ramp:
      forcing.breakpoints = {d.t0};
      break;
    case DriveType::Sine:
      forcing.breakpoints = {d.t0};
      break;
    case DriveType::Table:
      forcing.breakpoints.push_back(d.t0);
      for (const auto& [t, f] : d.table) forcing.breakpoints.push_back(d.t0 + t);
      break;
    case DriveType::Impulses:
      for (std::size_t i = 0; i < d.times.size(); ++i) {
        const double s = i < d.strengths.size() ? d.strengths[i] : 1.0;
        forcing.kicks.push_back({d.t0 + d.times[i], s});
      }
      std::sort(forcing.kicks.begin(), forcing.kicks.end(),
                [](const Kick& a, const Kick& b) { return a.tau < b.tau; });
      return forcing;  // no continuous force
    case DriveType::Expr: {
      auto fn = std::make_shared<ExprFunction>();
      try {
        fn->parser.DefineVar("t", &fn->t);
        fn->parser.DefineConst("pi", std::numbers::pi);
        fn->parser.SetExpr(d.expr);
        fn->parser.Eval();  // surfaces syntax errors and unknown variables now
      } catch (const mu::Parser::exception_type& e) {
        throw DriveError("drive.expr \"" + d.expr + "\": " + e.GetMsg() +
                         " (write an expression in t, e.g. \"0.02*t\" or \"sin(t/10)\")");
      }
      const double t0 = d.t0;
      forcing.f = [fn, t0](double tau) {
        if (tau < t0) return 0.0;
        fn->t = tau - t0;
        return fn->parser.Eval();
      };
      forcing.breakpoints = {d.t0};
      return forcing;
    }
  }
  forcing.f = [d](double tau) { return drive_value(d, tau); };
  forcing.f_many = [d](const double* tau, double* out, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) out[i] = drive_value(d, tau[i]);
  };
  std::sort(forcing.breakpoints.begin(), forcing.breakpoints.end());
  forcing.breakpoints.erase(std::unique(forcing.breakpoints.begin(), forcing.breakpoints.end()),
                            forcing.breakpoints.end());
  return forcing;
}

void load_drive_table(DriveDesc& drive, const std::string& path) {
  // Checked before reading: /dev/zero or a pipe would be read until memory runs out.
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw DriveError(path +
                     ": not a regular file (a device, pipe or folder); a drive table "
                     "is a CSV file of tau,f rows");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > kMaxDriveTableBytes)
    throw DriveError(path + ": " + std::to_string(size) + " bytes is more than the limit of " +
                     std::to_string(kMaxDriveTableBytes) + " bytes (" +
                     std::to_string(kMaxDriveTableBytes >> 20) +
                     " MiB) for a drive table; thin the table out, or use an expr drive");
  std::ifstream in(path);
  if (!in)
    throw DriveError(
        path + ": cannot read the drive table (check the path; it is relative to the scene file)");
  drive.table = parse_drive_table(in, path);
}

std::vector<std::pair<double, double>> parse_drive_table(std::istream& in,
                                                         const std::string& path) {
  std::vector<std::pair<double, double>> rows;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    double t = 0.0, f = 0.0;
    if (!(fields >> t >> f)) {
      if (rows.empty() && line_no == 1) continue;  // a header line such as "tau,f"
      throw DriveError(path + ":" + std::to_string(line_no) +
                       ": expected two numbers \"tau,f\", got \"" + line + "\"");
    }
    if (!rows.empty() && t <= rows.back().first)
      throw DriveError(path + ":" + std::to_string(line_no) +
                       ": tau must increase from row to row (got " + std::to_string(t) + " after " +
                       std::to_string(rows.back().first) + ")");
    rows.emplace_back(t, f);
  }
  if (rows.size() < 2)
    throw DriveError(path + ": a drive table needs at least two rows of \"tau,f\"");
  return rows;
}

}  // namespace cb
