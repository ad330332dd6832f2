#pragma once
// The report as a document: what acobench's analysis says about a study, as blocks of text, tables
// and figures, drawn by two renderers. Both draw the same blocks, so the Markdown and the HTML
// report cannot disagree; a renderer leaves out only what its medium cannot show (Markdown, the
// figures).
#include <string>
#include <variant>
#include <vector>

namespace aco::studies {

struct Paragraph {
  std::string text;  // plain text; Markdown's inline code (`name`) is kept as typed
  // Says in words what the figures beside it show: only where a renderer draws no figures.
  bool stands_in_for_figures = false;
};

struct Warning {
  std::string text;
};

struct Table {
  std::string title;  // a section heading
  std::string intro;  // "" for none
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // Per column, 'l' (text) or 'r' (numbers): how Markdown aligns it. Columns past its end are
  // right-aligned; the default puts the first two on the left.
  std::string alignment = "ll";
};

// An SVG drawing, shown in the page and also written alone as plots/<file>; or, when it could not
// be drawn, why (`svg` empty).
struct Figure {
  std::string file;
  std::string svg;
  std::string not_drawn;
};

using Block = std::variant<Paragraph, Warning, Table, Figure>;

struct ReportDocument {
  std::string title;
  std::string short_title;  // a browser tab's
  std::vector<Block> blocks;
};

std::string render_markdown(const ReportDocument& document);
// A self-contained page; `footer_html` goes last in its body.
std::string render_html(const ReportDocument& document, const std::string& footer_html = "");

}  // namespace aco::studies
