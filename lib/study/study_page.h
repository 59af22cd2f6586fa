#pragma once
// The pieces of a report the data-parallel and out-of-core studies write for themselves (the
// single-machine study's report is study_report.h): a table as Markdown and as HTML from one
// list of cells, an image as EXR + PNG, and the page that shows the table, the notes and the
// images beside the reference.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "util/image.h"

namespace proxyvis {

// One table: its header, Markdown's alignment per column ('l' or 'r') and its rows' cells.
struct TextTable {
  std::vector<std::string> header;
  std::string align;
  std::vector<std::vector<std::string>> rows;
};
std::string markdownTable(const TextTable& table);
std::string htmlTable(const TextTable& table);

// `image` as `stem`.exr (full float) and `stem`.png at `exposure`.
void writeImagePair(const Image& image, const std::filesystem::path& stem, float exposure);

// A study's report in `dir`: report.json, report.md, report.html (studyPageHtml of `title`,
// `table_html` and `notes`) and images/ with the reference and each named image as EXR + PNG,
// all at the reference's exposure.
struct StudyReportFiles {
  std::string json, markdown, title, table_html;
  std::vector<std::string> notes;
  const Image* reference = nullptr;
  std::vector<std::pair<std::string, const Image*>> images;  // name (no extension), image
};
void writeStudyReport(const std::filesystem::path& dir, const StudyReportFiles& files);

// The report page: a heading, the table, the notes (one paragraph each, escaped) and every
// image of images/ named in `images` (without extension), the reference first.
std::string studyPageHtml(const std::string& title, const std::string& table_html,
                          const std::vector<std::string>& notes,
                          const std::vector<std::string>& images);

}  // namespace proxyvis
