#include "figure_cairo/figure_output.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>
#include <cassert>
#include <cstring>
#include <stdexcept>

#include "figure_cairo/cairo_handles.h"
#include "figure_cairo/figure_draw.h"
#include "figure_cairo/svg_text.h"

namespace cb {

namespace {

void check(cairo_surface_t* surface, const char* what) {
  const cairo_status_t status = cairo_surface_status(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cairo could not ") + what + ": " +
                             cairo_status_to_string(status));
}

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

const char* figure_format_name(FigureFormat format) {
  switch (format) {
    case FigureFormat::Svg:
      return "svg";
    case FigureFormat::Pdf:
      return "pdf";
    case FigureFormat::Png:
      break;
  }
  return "png";
}

std::optional<std::vector<FigureFormat>> parse_figure_formats(const std::string& text) {
  std::vector<FigureFormat> formats;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, end - start);
    std::optional<FigureFormat> format;
    for (FigureFormat f : {FigureFormat::Png, FigureFormat::Svg, FigureFormat::Pdf})
      if (name == figure_format_name(f)) format = f;
    if (!format || std::find(formats.begin(), formats.end(), *format) != formats.end())
      return std::nullopt;
    formats.push_back(*format);
    start = end + 1;
  }
  return formats;
}

Image figure_image(const Figure& figure, const Theme& theme, int width, int height) {
  CairoSurface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  check(surface.get(), "make an image surface");
  {
    const CairoContext cr(cairo_create(surface.get()));
    draw_figure(cr.get(), figure, theme, width, height);
  }
  cairo_surface_flush(surface.get());
  // RGB24: one 32-bit word a pixel, 0x00RRGGBB in the machine's byte order.
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(row[x] >> 16);
      p[1] = static_cast<std::uint8_t>(row[x] >> 8);
      p[2] = static_cast<std::uint8_t>(row[x]);
      p[3] = 255;
    }
  }
  return image;
}

std::string figure_vector(const Figure& figure, const Theme& theme, FigureFormat format, int width,
                          int height) {
  assert(format != FigureFormat::Png);
  std::string bytes;
  {
    CairoSurface surface;
    double scale = 1.0;
    if (format == FigureFormat::Svg) {
      surface.reset(cairo_svg_surface_create_for_stream(append, &bytes, width, height));
      check(surface.get(), "start an SVG document");
      cairo_svg_surface_restrict_to_version(surface.get(), CAIRO_SVG_VERSION_1_1);
      cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
    } else {
      scale = kPdfScale;
      surface.reset(
          cairo_pdf_surface_create_for_stream(append, &bytes, scale * width, scale * height));
      check(surface.get(), "start a PDF document");
      cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE,
                                     (figure.name + ": " + figure.caption).c_str());
      cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR,
                                     "chainbreak figures");
    }
    SvgTextLayer text;  // before the context, which points to it
    {
      const CairoContext cr(cairo_create(surface.get()));
      if (format == FigureFormat::Svg) text.attach(cr.get());
      cairo_scale(cr.get(), scale, scale);
      draw_figure(cr.get(), figure, theme, width, height);
    }
    cairo_surface_finish(surface.get());
    check(surface.get(), format == FigureFormat::Svg ? "write the SVG" : "write the PDF");
    if (format == FigureFormat::Svg) return text.insert_into(bytes);
  }
  return bytes;
}

}  // namespace cb
