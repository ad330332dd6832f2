#pragma once
// The report's figures: charts and pictures of the maps with paths, each drawn inline in
// report.html and also written alone as plots/<file>, so that a page (the project's
// docs/results.md) can show one as an image.
#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "aco/studies/report_document.hpp"
#include "report_analysis.hpp"

namespace aco::studies {

// The figures' file names, each used once.
class FigureFiles {
 public:
  // A figure whose file name is made of `name` (characters unsafe in a file name become '-', a
  // name already taken gets -2, -3, ...).
  Figure add(const std::string& name, std::string svg);

 private:
  std::set<std::string> taken_;
};

// IOHanalyzer's fixed-target ECDF, one chart per target: per configuration, the share of its
// (problem, run) pairs within the target by each time.
std::vector<Figure> ecdf_charts(const Analysis& a, FigureFiles& files);
// Problem p's figures: the final lengths' box plot, the best-so-far length's convergence, the
// anytime charts and the map with each configuration's best path.
std::vector<Figure> problem_figures(const Analysis& a, std::size_t p, FigureFiles& files);
// The ablation path's mean gap per step (none without an ablation path).
std::vector<Figure> ablation_charts(const Analysis& a, FigureFiles& files);

}  // namespace aco::studies
