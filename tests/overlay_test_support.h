// Shared by the overlay tests (test_overlay.cpp without GL, test_overlay_gl.cpp with it).
#pragma once

#include <limits>

#include "drive/drive.h"
#include "physics/chain.h"

namespace cb::overlay_test {

inline cb::DriveDesc ramp(double beta) {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = beta;
  return d;
}

inline cb::ChainParams chain(int beads,
                             double threshold = std::numeric_limits<double>::infinity()) {
  cb::ChainParams p;
  p.beads = beads;
  p.threshold = threshold;
  return p;
}

}  // namespace cb::overlay_test
