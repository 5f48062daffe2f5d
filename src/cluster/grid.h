// A sweep's grid of parameters as plain data: named axes, each a list of values, and their
// cartesian product numbered with the first axis slowest (point 0 is every axis's first
// value). No scene, no I/O: the same structs can be filled and read from a Python module.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb {

// A grid spec a user can fix (COUNT 0, a log axis through zero, a key given twice): the
// message says what, where (the option as typed) and how to fix it. The app exits with 2.
struct GridError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct GridAxis {
  std::string key;             // scene key, e.g. "chain.threshold"
  std::vector<double> values;  // in sweep order
  std::string spec;            // as typed: "--vary chain.threshold=1:300:420"
};

struct Grid {
  std::vector<GridAxis> axes;  // first axis slowest

  std::size_t size() const;  // product of the axes' lengths (0 without axes)
  // The values of point `index` (< size()), one per axis.
  std::vector<double> point(std::size_t index) const;
  // The same into `values` (its storage reused: a sweep's rows, one after another).
  void point_into(std::size_t index, std::vector<double>& values) const;
  // Point `index`'s place in the grid of the axes `kept` (kept[k] for axis k) alone: points
  // with the same values on those axes share it.
  std::size_t index_on(std::size_t index, const std::vector<bool>& kept) const;
  // CSV header: "value,spring,tau" for one axis (the historical header scripts read),
  // otherwise one column per key then "spring,tau".
  std::string csv_header() const;
};

// Keys whose values are whole numbers (chain.seed, chain.beads, render.width, render.height):
// parse_vary rounds their spaced values to the nearest integer (1 + w (10000 - 1) is not always
// a whole number), and the sweep's CSV writes them as integers (issue #23: seeds).
bool whole_number_key(const std::string& key);

// KEY=LO:HI:COUNT[:log]: COUNT values from LO to HI, evenly spaced (geometrically with :log).
GridAxis parse_vary(const std::string& text);
// KEY=V1,V2,...: an explicit list, in the order given.
GridAxis parse_values(const std::string& text);
// Appends `axis`, refusing a key the grid already varies.
void add_axis(Grid& grid, GridAxis axis);
// Refuses grids whose point count does not fit (each axis's count multiplied).
void check_grid_size(const Grid& grid, std::size_t limit);

}  // namespace cb
