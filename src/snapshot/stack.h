// Side-by-side runs: frames of several runs, each laid out at its own height, stacked top to
// bottom into one frame (plain data: every shape moved down by its panel's offset), with a
// label naming each run and a rule between them; and the title card that opens a video.
#pragma once

#include <string>
#include <vector>

#include "snapshot/snapshot.h"

namespace cb {

// parts[i] was built at width x (its own height); they fill `height` top to bottom.
RenderSnapshot stack_snapshots(std::vector<RenderSnapshot> parts, const std::vector<std::string>& labels,
                               int width, int height, ThemeName theme);

// A frame of text only: a title, lines of parameters, and the question, centred.
RenderSnapshot title_card(int width, int height, ThemeName theme, const std::string& title,
                          const std::vector<std::string>& lines, const std::string& question);

}  // namespace cb
