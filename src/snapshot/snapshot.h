// RenderSnapshot: everything one frame shows, as plain data in pixel coordinates (origin
// top-left, y down), built from the physics state with no GL (MuJoCo's mjvScene). The
// renderer draws it and nothing else; tests check it exactly without a GPU.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "physics/chain.h"
#include "snapshot/break_labels.h"
#include "text/text_layout.h"
#include "theme/theme.h"

namespace cb {

struct OverlayData;  // overlay/overlay_data.h: what the HUD and plots show (plain data)

// Vertical (issue #22): the longitudinal view turned upright, for a hanging chain (the default
// when chain.gravity > 0): bead 0 is the ceiling, beads go down, the force pulls down.
enum class View { Longitudinal, Transverse, Both, Vertical };
bool parse_view(const std::string& text, View& out);
const char* view_name(View view);

struct Color {
  float r = 0, g = 0, b = 0, a = 1;  // linear 0..1 values as written to an 8-bit sRGB image
};

struct BeadInstance {
  float x = 0, y = 0;  // centre, pixels
  float radius = 0;    // pixels
  Color color;
};

// A spring between two points, drawn as a coil (or a bar when short), coloured by strain.
struct SpringInstance {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // end points, pixels
  float width = 0;                       // coil amplitude / bar thickness, pixels
  float coils = 0;                       // number of turns; 0 draws a straight bar
  Color color;
};

struct Segment {  // a straight line of some thickness (wall hatch, arrow shaft, string, ticks)
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  float width = 1;
  Color color;
};

struct Triangle {  // filled (arrow heads)
  float x[3] = {0, 0, 0}, y[3] = {0, 0, 0};
  Color color;
};

struct Rect {  // filled axis-aligned rectangle (wall, colour bar cells, flash, panels)
  float x = 0, y = 0, w = 0, h = 0;
  Color color;
};

// A line of text in the project's typeface (UTF-8 with real glyphs: τ, φ, ψ; "_c" and "_{N/2}"
// are subscripts), laid out by text/text_layout.h: text_width(text, size, face) is exactly
// the width the renderer draws.
struct Label {
  std::string text;
  float x = 0, y = 0;  // left edge and the top of its capitals, pixels
  float size = 14;     // pixel height of the font (ascent - descent), as Dear ImGui's
  Color color;
  FontFace face = FontFace::Sans;
};

// A grid of columns x rows colours (RGBA8, rows top-down) stretched over a pixel rectangle,
// each cell a sharp block: one textured quad where one rect per cell (the page's space-time
// picture, up to 512 x 256 cells) cost SwiftShader more than the rest of the frame.
struct Picture {
  float x = 0, y = 0, w = 0, h = 0;  // pixels
  int columns = 0, rows = 0;
  std::vector<std::uint8_t> rgba;  // columns * rows * 4
};

// One drawing layer; layers are drawn in order (back to front), each shape kind in one
// draw call (pictures, one call each, right after the layer's rects and segments).
struct Layer {
  std::vector<Rect> rects;
  std::vector<Segment> segments;
  std::vector<Triangle> triangles;
  std::vector<SpringInstance> springs;
  std::vector<BeadInstance> beads;
  std::vector<Label> labels;
  std::vector<Picture> pictures;
};

// Layers, back to front. Tests and overlays may rely on this order.
enum SnapshotLayer : int {
  kLayerFrame = 0,  // wall, rest line, legend, panel captions
  kLayerChain,      // springs, the strain ribbon, recoiling halves of broken springs
  kLayerBeads,      // beads
  kLayerForce,      // pull string and force arrow
  kLayerMarks,      // break flashes and markers, time label
  kLayerCount
};

// One chain panel. Longitudinal: bead j at x_wall + (j + psi_j) * spacing, y = centre_y.
// Transverse: bead j at x_wall + j * spacing, y = centre_y - psi_j * psi_scale.
// Vertical: bead j at x = chain_x, y = ceiling_y + (j + psi_j) * spacing.
struct PanelLayout {
  View view = View::Longitudinal;  // Longitudinal, Transverse or Vertical, never Both
  float top = 0, bottom = 0;       // the panel's extent, pixels
  float centre_y = 0;              // the chain's rest line
  float half_height = 0;           // transverse: pixels from the rest line to |psi| = psi_range
  float spacing = 0;               // pixels per unit of rest length
  float psi_scale = 0;             // pixels per unit of psi (longitudinal: = spacing)
  float bead_radius = 0;  // a bead of the median mass (bead j: bead_radius * sqrt(area ratio))
  float largest_bead_radius = 0;  // the heaviest bead's (bead_radius for equal masses)
  float spring_width = 0;  // SpringInstance::width of an intact spring of the median stiffness
  float coils = 0;         // SpringInstance::coils of an intact spring (0: bars)
  float ribbon_width = 0;  // thickness of the strain ribbon, pixels
  float wall_half_height = 0;
  float markers_top = 0;  // y of the first row of break markers
  // Vertical: the chain's column and the ceiling's face (bead 0), and the left edge of the
  // column of break labels right of the chain.
  float chain_x = 0, ceiling_y = 0, labels_x = 0;
};

// Where everything goes, from the style and N alone: the same for every frame of a video.
struct SnapshotLayout {
  float margin = 0;
  float font_px = 0;        // labels' pixel height: frame_text_px(frame height), as the overlay's
  float text_size = 0;      // the layout's unit: the labels' cap height, pixels
  float x_wall = 0;         // the wall's face, x of bead 0
  float x_right = 0;        // bead N at psi_N = psi_range (longitudinal) or at rest (transverse)
  float arrow_max = 0;      // length of the force arrow at |f| = force_range
  float string_length = 0;  // pull string from bead N to the arrow (0 without a string)
  bool ribbon = false;      // beads less than ~3 px apart: draw the strain ribbon
  int panel_count = 0;
  PanelLayout panels[2];
  float legend_x = 0, legend_y = 0, legend_w = 0, legend_h = 0;  // the colour bar
  // The beads the panels span: first_bead at the wall's face (0: the wall itself), last_bead
  // at the right end (N unless zoomed).
  int first_bead = 0, last_bead = 0;
  bool zoomed() const { return first_bead > 0 || last_bead_limited; }
  bool last_bead_limited = false;
  float overview_x = 0, overview_y = 0, overview_w = 0, overview_h = 0;  // zoom: the whole chain
  float caption_y = 0;  // top of the caption's capitals (when there is one)
};

// One placed label of a break (or of the "+k more" count), for tests and overlays.
struct BreakLabelBox {
  int spring = -1;     // the spring it names (0: the pull string); -1: "+k more"
  bool first = false;  // the first break: accent pointer and leader, bold text
  LabelBox box;        // the label's line box (ascent to descent), pixels
};

struct RenderSnapshot {
  int width = 0, height = 0;  // pixels
  Color background;
  double tau = 0.0;
  double force = 0.0;
  // What is in the layers, for tests and overlays.
  int beads = 0;        // N
  bool ribbon = false;  // beads under ~3 px apart: springs drawn as a strain ribbon
  std::vector<BreakEvent> breaks_shown;  // breaks with tau <= this tau (markers on screen)
  // The labels of breaks_shown, as placed (snapshot/break_labels.h): their boxes never
  // intersect and the first break's is always there; breaks_unlabelled are counted in a
  // "+k more" label (or in the first label's text when even that found no room).
  std::vector<BreakLabelBox> break_labels;
  int breaks_unlabelled = 0;
  // Force arrow, tail to tip, pixels: > 0 along +psi (right; vertical view: down), < 0
  // against it; 0: none.
  double arrow_length = 0.0;
  SnapshotLayout layout;
  std::vector<Layer> layers;  // kLayerCount layers, in SnapshotLayer order
  // The HUD and plots drawn over the frame by the overlay (src/overlay), filled on the physics
  // side; null: no overlay. Shared and immutable, so the GL thread reads it without copying.
  std::shared_ptr<const OverlayData> overlay;
};

// How a frame is laid out; the same for every frame of a video so nothing jumps.
struct SnapshotStyle {
  int width = 1280, height = 720;
  ThemeName theme = ThemeName::Dark;
  View view = View::Longitudinal;
  // The largest |psi| expected in the run (> 0): the longitudinal view fits bead N at
  // psi_N = psi_range, the transverse view maps |psi| = psi_range to the panel's half height.
  // Choose it from the wall-side part's maximum: a detached part may then leave the frame.
  double psi_range = 1.0;
  double force_range = 1.0;   // the largest |f| expected (arrow length)
  double threshold = 0.0;     // phi_c for the colour scale; <= 0: scale by strain_range
  double strain_range = 1.0;  // |phi| that maps to the end of the colour scale when unbreakable
  // The chain, its colour bar and the time label keep to the top `chain_height` pixels of the
  // frame, leaving the rest to the overlay's plots; 0 (or the frame's height): the whole frame.
  // Text size and margins still follow the whole frame, so they match the overlay's.
  int chain_height = 0;
  // Zoom: springs zoom_first..zoom_last (1-based, first < last) drawn across the panel, with an
  // overview bar of the whole chain marking where they sit; 0, 0: the whole chain. In the
  // longitudinal view the window moves with bead zoom_first - 1, so the stretch stays in view.
  int zoom_first = 0, zoom_last = 0;
  std::string caption;  // a line of text centred under the chain (above the colour bar)
};

// The strain colour map: s = phi_j / phi_c,j in [-1, 1] (clamped): how close spring j is to
// breaking under its own threshold (phi / phi_c for the uniform chain; phi / strain_range for
// an unbreakable one). Diverging (compression blue,
// tension orange) with lightness rising monotonically from s = -1 to s = +1, so compression
// and tension differ in greyscale print and for colour-blind viewers; saturates visibly
// (towards a hot, brighter tone) as |s| approaches 1.
Color strain_color(double s, ThemeName theme);
Color strain_color(double s);  // the dark theme's

// How the chain's coefficients show (issue #21): a bead's area follows its mass and a spring's
// width (coil amplitude and wire) its stiffness, relative to the chain's median and clamped so
// that every bead and spring stays readable. Empty for a uniform mass or stiffness (every
// ratio 1), so the paper's chain is drawn exactly as before.
inline constexpr double kBeadAreaRange = 4.0;     // areas from 1/4 to 4 x the median bead's
inline constexpr double kSpringWidthRange = 2.0;  // widths from 1/2 to 2 x the median spring's
std::vector<double> bead_area_ratios(const ChainParams& params);     // bead j at j-1
std::vector<double> spring_width_ratios(const ChainParams& params);  // spring j at j-1

// The layout build_snapshot uses for this style and chain.
SnapshotLayout snapshot_layout(const SnapshotStyle& style, const ChainParams& params);

// Marks a frame of a slowed-down video: "×0.1 slow motion" at the top right, in the theme's
// text colour over an accent underline (speed: this frame's speed relative to normal).
void add_slow_motion_tag(RenderSnapshot& snapshot, double speed, ThemeName theme);

// Builds the frame for the chain in `state` (bead j's psi in state.psi[j-1]) under force f.
RenderSnapshot build_snapshot(const ChainState& state, const ChainParams& params, double force,
                              const SnapshotStyle& style);

}  // namespace cb
