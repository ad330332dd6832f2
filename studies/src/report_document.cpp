#include "aco/studies/report_document.hpp"

#include <sstream>

#include "aco/drawing/svg.hpp"

namespace aco::studies {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
// Clang 14 (the fuzz preset) deduces no aggregate's template arguments without it.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

void markdown_table(std::ostringstream& md, const Table& t) {
  md << "## " << t.title << "\n\n";
  if (!t.intro.empty()) md << t.intro << "\n\n";
  md << "|";
  for (const auto& h : t.header) md << " " << h << " |";
  md << "\n|";
  for (std::size_t i = 0; i < t.header.size(); ++i)
    md << (i < t.alignment.size() && t.alignment[i] == 'l' ? "---|" : "---:|");
  md << "\n";
  for (const auto& row : t.rows) {
    md << "|";
    for (const auto& cell : row) md << " " << cell << " |";
    md << "\n";
  }
  md << "\n";
}

void html_table(std::ostringstream& out, const Table& t) {
  out << "<h2>" << aco::xml_escape(t.title) << "</h2>\n";
  if (!t.intro.empty()) out << "<p>" << aco::xml_escape(t.intro) << "</p>\n";
  out << "<table><tr>";
  for (const auto& h : t.header) out << "<th>" << aco::xml_escape(h) << "</th>";
  out << "</tr>\n";
  for (const auto& row : t.rows) {
    out << "<tr>";
    for (const auto& cell : row) out << "<td>" << aco::xml_escape(cell) << "</td>";
    out << "</tr>\n";
  }
  out << "</table>\n";
}

}  // namespace

std::string render_markdown(const ReportDocument& document) {
  std::ostringstream md;
  md << "# " << document.title << "\n\n";
  for (const Block& block : document.blocks)
    std::visit(Overloaded{
                   [&](const Paragraph& p) { md << p.text << "\n\n"; },
                   [&](const Warning& w) { md << "> **Warning:** " << w.text << "\n\n"; },
                   [&](const Table& t) { markdown_table(md, t); },
                   [](const Figure&) {},
               },
               block);
  return md.str();
}

std::string render_html(const ReportDocument& document, const std::string& footer_html) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
      << aco::xml_escape(document.short_title)
      << "</title><style>body{font-family:sans-serif;margin:2em;max-width:1400px}table{border-collapse:collapse;"
         "margin:1em 0}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}td:first-child,th:first-child{"
         "text-align:left}svg{margin:0.5em}.warning{background:#fff3cd;border:1px solid #e0a800;padding:0.5em}</style>"
         "</head><body>\n<h1>"
      << aco::xml_escape(document.title) << "</h1>\n";
  for (const Block& block : document.blocks)
    std::visit(Overloaded{
                   [&](const Paragraph& p) {
                     if (!p.stands_in_for_figures) out << "<p>" << aco::xml_escape(p.text) << "</p>\n";
                   },
                   [&](const Warning& w) {
                     out << "<p class=\"warning\"><strong>Warning:</strong> " << aco::xml_escape(w.text) << "</p>\n";
                   },
                   [&](const Table& t) { html_table(out, t); },
                   [&](const Figure& f) {
                     out << (f.svg.empty() ? "<p>" + aco::xml_escape(f.not_drawn) + "</p>" : f.svg) << "\n";
                   },
               },
               block);
  out << footer_html << "</body></html>\n";
  return out.str();
}

}  // namespace aco::studies
