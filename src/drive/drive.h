// The pulling force f(tau): what a scene asks for (DriveDesc) and how the integrator
// gets it (make_forcing). A drive starts at t0: f(tau) = g(tau - t0) for tau >= t0, 0 before.
#pragma once

#include <cstdint>
#include <istream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "physics/forcing.h"

namespace cb {

enum class DriveType { Step, Ramp, Sine, Impulses, Table, Expr };

struct DriveDesc {
  DriveType type = DriveType::Ramp;
  double amplitude = 1.0;                        // step: A; sine: A
  double beta = 1.0;                             // ramp: f = beta (tau - t0)
  double period = 120.0;                         // sine: A sin(2 pi (tau - t0) / period)
  std::vector<double> times;                     // impulses: kick times relative to t0
  std::vector<double> strengths;                 // impulses: kick sizes; empty = all 1
  std::string table_file;                        // table: CSV of tau,f (as written in the scene)
  std::vector<std::pair<double, double>> table;  // table: loaded points, tau ascending
  std::string expr;                              // expr: muParser expression in t (= tau - t0)
  double t0 = 0.0;
};

const char* drive_type_name(DriveType type);
bool parse_drive_type(const std::string& name, DriveType& out);

// The value f(tau) of every drive except Expr (which needs muParser); impulses give 0
// (they are kicks, not a force). Right-continuous at a step's jump.
double drive_value(const DriveDesc& drive, double tau);

// Compiles the drive for the integrator. Throws DriveError for a bad expression.
Forcing make_forcing(const DriveDesc& drive);

// The largest table file load_drive_table reads: some 3 million rows, far more than a
// drive needs; a bigger file (or /dev/zero, which never ends) is a mistake.
inline constexpr std::uintmax_t kMaxDriveTableBytes = 64u << 20;

// Loads a CSV of "tau,f" rows (an optional header line, '#' comments) into drive.table.
// Throws DriveError naming the file, the line and what is wrong; refuses what is not a
// regular file (a device, a pipe, a folder) and files over kMaxDriveTableBytes.
void load_drive_table(DriveDesc& drive, const std::string& path);
// The same from a stream already open (`path` names it in messages): the fuzzer's entry.
std::vector<std::pair<double, double>> parse_drive_table(std::istream& in, const std::string& path);

struct DriveError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace cb
