// [drive]: which force pulls bead N, validated and converted to f(tau) of Eq. (dimless).
//
// Every key present is type-checked whatever the drive type, but only the type's own keys
// are required: `--set drive.type=step` on a ramp scene must not trip over its beta.
#include <filesystem>

#include "scene/scene_sections.h"

namespace cb::scene_detail {

namespace {

const std::vector<std::string_view> kDriveTypes = {"step",     "ramp",  "sine",
                                                   "impulses", "table", "expr"};

std::string needs(const char* type, const char* what) {
  return std::string("(type = \"") + type + "\" needs " + what + ")";
}

void read_impulses(const SceneReader& r, const Conversion& c, DriveDesc& d) {
  const auto times = r.numbers("drive", "times");
  const auto strengths = r.numbers("drive", "strengths");
  if (!times) {
    r.fail_missing("drive", "times", needs("impulses", "the kick times"));
    return;
  }
  for (double t : *times) d.times.push_back(c.time(t));
  // Kicks default to strength 1 in the scene's units (1 N s for SI input), so with SI input
  // the converted defaults are written out. validate() checks the counts agree.
  if (strengths)
    for (double s : *strengths) d.strengths.push_back(c.impulse(s));
  else if (c.si)
    d.strengths.assign(times->size(), c.impulse(1.0));
}

// The table's rows as the scene gives them, before unit conversion: inline (`points`, tau
// and f pairs; what the scene writer uses for converted SI tables) or from a CSV file.
void read_table_rows(const SceneReader& r, const std::string& scene_dir, DriveDesc& d) {
  const auto points = r.numbers("drive", "points");
  const auto file = r.string("drive", "file");
  if (points && file) {
    r.fail("drive", "points", "give the table either as drive.file or as drive.points, not both");
    return;
  }
  if (points || r.failed("drive", "points")) {
    if (!points) return;
    if (points->size() < 4 || points->size() % 2 != 0) {
      r.fail("drive", "points",
             "drive.points holds tau, f pairs: an even count of numbers, at least two pairs, "
             "e.g. points = [0.0, 0.0, 50.0, 1.0]");
      return;
    }
    // validate() checks that tau increases.
    for (std::size_t i = 0; i < points->size(); i += 2)
      d.table.emplace_back((*points)[i], (*points)[i + 1]);
    return;
  }
  const auto given = r.require_string("drive", "file", needs("table", "a CSV file of tau,f rows"));
  if (!given) return;
  d.table_file = *given;
  // Relative to the scene file, so a scene and its data move together.
  const std::filesystem::path path =
      std::filesystem::path(scene_dir) / std::filesystem::path(d.table_file);
  try {
    load_drive_table(d, path.string());
  } catch (const DriveError& e) {
    // The DriveError names the resolved path, the row and what to fix.
    r.fail("drive", "file", "cannot use drive.file = \"" + d.table_file + "\": " + e.what());
    d.table.clear();
  }
}

void read_table(const SceneReader& r, const Conversion& c, const std::string& scene_dir,
                DriveDesc& d) {
  read_table_rows(r, scene_dir, d);
  for (auto& [t, f] : d.table) {
    t = c.time(t);
    f = c.force(f);
  }
}

void read_expr(const SceneReader& r, const Conversion& c, DriveDesc& d) {
  const auto expr = r.require_string("drive", "expr", needs("expr", "an expression in t"));
  if (!expr) return;
  d.expr = *expr;
  if (!c.si) return;  // validate() compiles it
  // Compiled as the user wrote it first, so that muParser's message quotes their text.
  try {
    make_forcing(d);
  } catch (const DriveError& e) {
    r.fail("drive", "expr", std::string(e.what()));
    return;
  }
  d.expr = expr_to_dimensionless(d.expr, c);
}

}  // namespace

DriveDesc read_drive(const SceneReader& r, const Conversion& c, const std::string& scene_dir) {
  DriveDesc d;
  const auto type =
      r.require_string("drive", "type", "(one of step, ramp, sine, impulses, table, expr)");
  if (type && !parse_drive_type(*type, d.type))
    r.fail("drive", "type",
           "unknown drive type '" + *type + "'; " + suggest(*type, kDriveTypes, "\"", "\""));
  // Without a type the required keys are unknown: type-check what is there, require nothing.
  const bool typed = type && !r.failed("drive", "type");

  // Read (and so type-check) every key up front, required or not.
  const auto amplitude = r.number("drive", "amplitude");
  const auto beta = r.number("drive", "beta");
  const auto period = r.number("drive", "period");
  const auto t0 = r.number("drive", "t0");
  if (period) d.period = c.time(*period);  // checked by validate() whatever the type
  d.t0 = c.time(t0.value_or(0.0));
  // Keys of other drive types are type-checked here but otherwise ignored (a problem is noted
  // once, so reading them again below says nothing new).
  r.numbers("drive", "times");
  r.numbers("drive", "strengths");
  r.string("drive", "file");
  r.numbers("drive", "points");
  r.string("drive", "expr");

  if (!typed) {
    // A stand-in that validate() needs nothing more for; the type's problem is noted.
    d.type = DriveType::Step;
    d.amplitude = 0.0;
    return d;
  }
  switch (d.type) {
    case DriveType::Step:
      if (!amplitude) r.fail_missing("drive", "amplitude", needs("step", "the step's height"));
      if (amplitude) d.amplitude = c.force(*amplitude);
      break;
    case DriveType::Ramp:
      if (!beta) r.fail_missing("drive", "beta", needs("ramp", "the slope of f = beta tau"));
      if (beta) d.beta = c.slope(*beta);
      break;
    case DriveType::Sine:
      if (!amplitude) r.fail_missing("drive", "amplitude", needs("sine", "the amplitude"));
      if (!period) r.fail_missing("drive", "period", needs("sine", "the period"));
      if (amplitude) d.amplitude = c.force(*amplitude);
      break;
    case DriveType::Impulses:
      read_impulses(r, c, d);
      break;
    case DriveType::Table:
      read_table(r, c, scene_dir, d);
      break;
    case DriveType::Expr:
      read_expr(r, c, d);
      break;
  }
  return d;
}

}  // namespace cb::scene_detail
