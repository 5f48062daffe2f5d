// `chainbreak figures`: the paper's Figs. 3-5, the breaking maps and the one-body windows as
// PNG, SVG and/or PDF (drawn by the cairo backend, src/figure_cairo) + CSV.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <vector>

#include "app/commands.h"
#include "app/figure_csv.h"
#include "app/progress.h"
#include "figure_cairo/figure_output.h"
#include "figures/figure_specs.h"
#include "output/frame_writer.h"
#include "output/output_file.h"
#include "output/output_lock.h"
#include "output/png_writer.h"
#include "theme/fonts.h"

namespace cb {

namespace {

// --only fig4a,breaking_map: the names, checked against the list.
std::set<std::string> parse_only(const std::string& text) {
  std::set<std::string> names;
  std::string known;
  for (const FigureEntry& e : figure_entries()) known += (known.empty() ? "" : ", ") + e.name;
  std::size_t start = 0;
  while (!text.empty() && start <= text.size()) {
    const auto end = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, end - start);
    bool found = false;
    for (const FigureEntry& e : figure_entries()) found = found || e.name == name;
    if (!found) throw SceneError("--only " + text + ": no figure '" + name + "'; known: " + known);
    names.insert(name);
    start = end + 1;
  }
  return names;
}

void make_output_dir(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    throw OutputError("cannot create the folder " + dir + " (" + error.message() +
                      "): choose another with -o DIR");
  require_writable_dir(dir);
}

// One figure in one format, written whole or not at all; returns the file's path.
std::string write_figure(const Figure& figure, const Theme& theme, FigureFormat format,
                         const std::filesystem::path& stem) {
  const std::string path = stem.string() + "." + figure_format_name(format);
  if (format == FigureFormat::Png) {
    write_png(path, figure_image(figure, theme));
  } else {
    OutputFile file(path);
    file.write(figure_vector(figure, theme, format));
    file.commit();
  }
  return path;
}

}  // namespace

int figures_command(const FiguresOptions& o) {
  const std::set<std::string> only = parse_only(o.only);
  const std::optional<ThemeName> theme_id = parse_theme(o.theme);
  if (!theme_id)
    throw SceneError("--theme " + o.theme + ": no such theme; use light (paper) or dark");
  const std::optional<std::vector<FigureFormat>> formats = parse_figure_formats(o.formats);
  if (!formats)
    throw SceneError("--format " + o.formats +
                     ": expected png, svg, pdf or a comma-separated list of them without "
                     "repeats, e.g. --format png,svg,pdf");
  const Theme& theme = cb::theme(*theme_id);
  // The typeface first: a machine without it fails at once, not after the computing.
  for (FontFace face : {FontFace::Sans, FontFace::Bold}) font_path(face);
  make_output_dir(o.out_dir);
  // One `figures` per folder at a time (issue #12, row 9): the PNG/SVG/PDF and the CSV of a
  // figure then come from one run.
  const OutputLock lock((std::filesystem::path(o.out_dir) / "figures").string());
  FigureOptions options;
  options.jobs = o.jobs;
  options.stop = &g_interrupted;
  const auto start = std::chrono::steady_clock::now();
  int done = 0;
  const int total =
      only.empty() ? static_cast<int>(figure_entries().size()) : static_cast<int>(only.size());
  {
    Progress progress("figures", total, o.quiet, "figures");
    for (const FigureEntry& entry : figure_entries()) {
      if (!only.empty() && !only.count(entry.name)) continue;
      const auto left = [&] {
        return "after " + std::to_string(done) + " of " + std::to_string(total) +
               " figures (their PNG and CSV are complete)";
      };
      if (g_interrupted) return interrupted_status(left());
      const Figure figure = entry.build(options);
      if (g_interrupted) return interrupted_status(left());  // the figure may be incomplete
      const std::filesystem::path stem = std::filesystem::path(o.out_dir) / entry.name;
      // A figure is all its files or none: a signal between them removes the ones written
      // (the message promises that every PNG left has its CSV).
      std::vector<std::string> written;
      for (FigureFormat format : *formats) {
        written.push_back(write_figure(figure, theme, format, stem));
        if (g_interrupted) {
          for (const std::string& path : written) std::filesystem::remove(path);
          return interrupted_status(left());
        }
      }
      OutputFile csv(stem.string() + ".csv");
      csv.write(figure_csv(figure));
      csv.commit();
      for (const std::string& path : written) std::printf("%s\n", path.c_str());
      std::printf("%s.csv\n", stem.c_str());
      std::fflush(stdout);
      progress.update(++done);
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet)
    std::fprintf(stderr,
                 "figures: %d figures (%s, %s theme, %dx%d + CSV) written to %s in %.1f s\n", done,
                 o.formats.c_str(), theme_name(*theme_id), kFigureWidth, kFigureHeight,
                 o.out_dir.c_str(), seconds);
  return 0;
}

}  // namespace cb
