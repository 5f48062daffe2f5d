// Where the labels of a chain's breaks go, as plain rectangles (no GL, no text drawing): the
// first break's label always, later ones only where they overlap nothing, the rest counted in
// a "+k more" label.
//
// Design note: a fast pull breaks a cascade of springs within a few tau, close together, and
// labels in fixed rows piled up on each other and on each other's leader lines. This is a
// greedy placement over rows under the chain (the way map labels are usually placed). A slot
// is free when its box, grown sideways by `gap`, meets no placed box and no placed leader
// line, and its own leader line (straight down from the pointer to the row) meets no placed
// box. The requests come in priority order: the first break, then the later ones by time.
// The first break's label is placed before any other, so it is always there, in the highest
// row that lets the most later breaks be labelled (from the top row its text would bar every
// leader under it; below the cascade's staircase it bars none). Which later
// breaks get a label goes by time: each joins when the labels chosen so far and it still lay
// out. Where they go, by position: from the rightmost anchor leftwards, each right of its
// leader in the first free row from the top, else left of it, so a cascade forms a staircase
// whose leaders pass left of the labels above them. The rest are counted in a "+k more" label
// placed by the same rule (no leader); if it finds no slot, the latest breaks' labels give
// theirs up. Boxes are the labels' full line boxes (ascent to descent), so "boxes do not
// intersect" means no two glyphs can touch.
#pragma once

#include <functional>
#include <vector>

namespace cb {

struct LabelBox {  // an axis-aligned box, pixels, y down
  double x = 0, y = 0, w = 0, h = 0;
  double right() const { return x + w; }
  double bottom() const { return y + h; }
  // Whether the two boxes share interior points once this one is grown by `gap` to the left
  // and right (boxes that only touch at an edge do not intersect). Rows keep their own
  // spacing, so no gap is asked for above and below.
  bool intersects(const LabelBox& o, double gap = 0.0) const;
};

// One break's label to place.
struct LabelRequest {
  double anchor_x = 0;    // the pointer's x: the leader line drops from here
  double leader_top = 0;  // where the leader line starts (the pointer's base), y
  double width = 0;       // the text's width, pixels
};

// The rows under a chain panel where labels may go, and the label's proportions.
struct LabelArea {
  double first_row_y = 0;       // top of the capitals of row 0
  double row_h = 1;             // from one row to the next (>= box_h, or rows would touch)
  int rows = 1;                 // >= 1
  double box_above = 0;         // from the top of the capitals up to the box's top (ascent - cap)
  double box_h = 1;             // the line's height (ascent - descent = the font's pixel size)
  double leader_end = 0;        // the leader line ends this far below the top of the capitals
  double x_min = 0, x_max = 1;  // boxes stay inside (unless a label is wider than this)
  double offset = 0;            // the text starts this far right of its leader (or ends left)
  double gap = 0;               // the clear space kept left and right of every box
};

struct PlacedLabel {
  int request = -1;  // index into the requests; -1 for the "+k more" label
  int row = 0;
  double x = 0, y = 0;  // the text's left edge and the top of its capitals (cb::Label)
  LabelBox box;
  bool has_leader = false;  // a vertical line at leader_x from leader_y0 down to leader_y1
  double leader_x = 0, leader_y0 = 0, leader_y1 = 0;
};

struct LabelPlan {
  std::vector<PlacedLabel> labels;  // labels[0] is request 0 when there are requests
  int dropped = 0;                  // requests without a label
  bool has_more = false;            // labels.back() is the "+k more" label (k = dropped)
  // No slot even for "+k more" next to the first label alone: the count is appended to the
  // first label's text instead (its box is already wide enough for it).
  bool more_in_first = false;
};

// `more_width(k)`: the width of the "+k more" label's text; `suffix_width(k)`: the width the
// first label gains when the count is appended to it.
LabelPlan place_labels(const std::vector<LabelRequest>& requests, const LabelArea& area,
                       const std::function<double(int)>& more_width,
                       const std::function<double(int)>& suffix_width);

}  // namespace cb
