// Greedy label placement for the breaks of a chain panel (see break_labels.h for the rule).
#include "snapshot/break_labels.h"

#include <algorithm>

namespace cb {

bool LabelBox::intersects(const LabelBox& o, double gap) const {
  return x - gap < o.right() && o.x < right() + gap && y < o.bottom() && o.y < bottom();
}

namespace {

// A leader line as a box of zero width, so one intersection test serves both.
LabelBox leader_box(const PlacedLabel& p) {
  return LabelBox{p.leader_x, p.leader_y0, 0.0, p.leader_y1 - p.leader_y0};
}

// The label of `width` at `row`, its text starting at `x` (clamped into the area), with a
// leader from (anchor_x, leader_top) when `leader`.
PlacedLabel slot(const LabelArea& a, int request, int row, double x, double width, bool leader,
                 double anchor_x, double leader_top) {
  PlacedLabel p;
  p.request = request;
  p.row = row;
  p.x = width <= a.x_max - a.x_min ? std::clamp(x, a.x_min, a.x_max - width) : a.x_min;
  p.y = a.first_row_y + row * a.row_h;
  p.box = LabelBox{p.x, p.y - a.box_above, width, a.box_h};
  p.leader_x = anchor_x;
  p.leader_y0 = leader_top;
  p.leader_y1 = p.y + a.leader_end;
  p.has_leader = leader && p.leader_y1 > p.leader_y0;
  return p;
}

bool is_free(const PlacedLabel& s, const std::vector<PlacedLabel>& placed, double gap) {
  // A box that its own leader would run into (clamped at the frame's edge over its anchor).
  if (s.has_leader && s.box.x < s.leader_x && s.leader_x < s.box.right()) return false;
  for (const PlacedLabel& p : placed) {
    if (s.box.intersects(p.box, gap)) return false;
    if (s.has_leader && leader_box(s).intersects(p.box, gap)) return false;
    if (p.has_leader && s.box.intersects(leader_box(p), gap)) return false;
  }
  return true;
}

// The first free slot for a break's label: right of its leader line in rows `rows` (from the
// top), then left of it. Right first, so that a cascade laid out from the right-hand break
// leftwards forms a staircase: each leader drops left of the labels above it.
bool place_request(const LabelArea& a, const LabelRequest& r, int index, double width,
                   const std::vector<int>& rows, const std::vector<PlacedLabel>& placed,
                   PlacedLabel& out) {
  for (const bool right : {true, false}) {
    const double x = right ? r.anchor_x + a.offset : r.anchor_x - a.offset - width;
    for (const int row : rows) {
      const PlacedLabel s = slot(a, index, row, x, width, true, r.anchor_x, r.leader_top);
      if (is_free(s, placed, a.gap)) {
        out = s;
        return true;
      }
    }
  }
  return false;
}

std::vector<int> all_rows(const LabelArea& a) {
  std::vector<int> rows(static_cast<std::size_t>(a.rows));
  for (int r = 0; r < a.rows; ++r) rows[r] = r;
  return rows;
}

// The first break's label in `row` (into an empty plan, so only its own leader can refuse a
// side; when both are refused, a label wider than the area, at the area's left edge).
PlacedLabel first_label(const LabelArea& a, const LabelRequest& r, double width, int row) {
  PlacedLabel p;
  if (!place_request(a, r, 0, width, {row}, {}, p))
    p = slot(a, 0, row, a.x_min, width, false, r.anchor_x, r.leader_top);
  return p;
}

// The first label in `first_row`, then the requests `chosen` from the rightmost anchor
// leftwards; false (with `out` partly filled) as soon as one of them finds no slot.
bool lay_out(const std::vector<LabelRequest>& requests, const std::vector<int>& chosen,
             const LabelArea& a, int first_row, std::vector<PlacedLabel>& out) {
  out.assign(1, first_label(a, requests[0], requests[0].width, first_row));
  std::vector<int> order = chosen;
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return requests[x].anchor_x > requests[y].anchor_x; });
  const std::vector<int> rows = all_rows(a);
  for (const int i : order) {
    PlacedLabel p;
    if (!place_request(a, requests[i], i, requests[i].width, rows, out, p)) return false;
    out.push_back(p);
  }
  return true;
}

// The "+k more" label: no leader. First at the area's left edge in any row (under the
// staircase, where the old fixed rows put it), then row by row a little right of every
// placed box (two gaps: any closer it would read as part of that label) and leader, and at
// the right edge.
bool place_more(const LabelArea& a, double width, const std::vector<PlacedLabel>& placed,
                PlacedLabel& out) {
  constexpr double kClear = 1e-6;  // (right + gap) - gap may round below right
  const auto try_at = [&](int row, double x) {
    const PlacedLabel s = slot(a, -1, row, x, width, false, 0.0, 0.0);
    if (!is_free(s, placed, a.gap)) return false;
    out = s;
    return true;
  };
  for (int row = 0; row < a.rows; ++row)
    if (try_at(row, a.x_min)) return true;
  std::vector<double> xs;
  for (const PlacedLabel& p : placed) {
    xs.push_back(p.box.right() + 2.0 * a.gap + kClear);
    if (p.has_leader) xs.push_back(p.leader_x + a.gap + kClear);
  }
  xs.push_back(a.x_max - width);
  for (int row = 0; row < a.rows; ++row)
    for (const double x : xs)
      if (try_at(row, x)) return true;
  return false;
}

}  // namespace

LabelPlan place_labels(const std::vector<LabelRequest>& requests, const LabelArea& area,
                       const std::function<double(int)>& more_width,
                       const std::function<double(int)>& suffix_width) {
  LabelPlan plan;
  if (requests.empty()) return plan;
  // Which later breaks get a label goes by time (the requests' order): each joins when the
  // labels chosen so far and it still lay out. Only the first kCandidates are tried: more
  // labels than that never fit under a chain, and a cascade may hold thousands of breaks.
  // The first label takes the highest row that labels the most breaks: from the top row its
  // text would bar every leader under it (a first break at the right edge runs left over the
  // cascade; one near the wall runs right over it), one row below the cascade's staircase
  // bars none.
  constexpr int kCandidates = 32;
  const int later = static_cast<int>(requests.size()) - 1;
  const int possible = std::min(later, kCandidates);
  std::vector<PlacedLabel> trial;
  int best_row = 0;
  std::vector<int> best;
  for (int first_row = 0; first_row < area.rows; ++first_row) {
    std::vector<int> chosen;
    for (int i = 1; i <= possible; ++i) {
      chosen.push_back(i);
      if (!lay_out(requests, chosen, area, first_row, trial)) chosen.pop_back();
    }
    if (first_row == 0 || chosen.size() > best.size()) {
      best = chosen;
      best_row = first_row;
    }
    if (static_cast<int>(best.size()) == possible) break;  // no row can do better
  }
  lay_out(requests, best, area, best_row, plan.labels);
  plan.dropped = later - static_cast<int>(best.size());
  if (plan.dropped == 0) return plan;
  // The count needs a slot of its own; the latest breaks' labels make room for it.
  for (;;) {
    PlacedLabel more;
    if (place_more(area, more_width(plan.dropped), plan.labels, more)) {
      plan.labels.push_back(more);
      plan.has_more = true;
      return plan;
    }
    if (plan.labels.size() == 1) break;
    const auto latest = std::max_element(
        plan.labels.begin() + 1, plan.labels.end(),
        [](const PlacedLabel& x, const PlacedLabel& y) { return x.request < y.request; });
    plan.labels.erase(latest);
    ++plan.dropped;
  }
  plan.more_in_first = true;
  plan.labels.front() =
      first_label(area, requests[0], requests[0].width + suffix_width(plan.dropped), best_row);
  return plan;
}

}  // namespace cb
