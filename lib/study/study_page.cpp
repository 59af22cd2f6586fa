#include "study/study_page.h"

#include <fmt/format.h>

#include "image/image_io.h"
#include "util/atomic_write.h"
#include "util/escape_html.h"

namespace proxyvis {

std::string markdownTable(const TextTable& table) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string t = "|";
    for (const std::string& c : cells) t += " " + c + " |";
    return t + "\n";
  };
  std::string t = line(table.header) + "|";
  for (char a : table.align) t += a == 'r' ? "---:|" : "---|";
  t += "\n";
  for (const auto& row : table.rows) t += line(row);
  return t;
}

std::string htmlTable(const TextTable& table) {
  std::string t = "<table><tr>";
  for (const std::string& h : table.header) t += "<th>" + escapeHtml(h) + "</th>";
  t += "</tr>";
  for (const auto& row : table.rows) {
    t += "<tr>";
    for (const std::string& c : row) t += "<td>" + escapeHtml(c) + "</td>";
    t += "</tr>";
  }
  return t + "</table>";
}

void writeImagePair(const Image& image, const std::filesystem::path& stem, float exposure) {
  ImageWriteOptions exr;
  exr.full_float = true;
  writeImage(image, stem.string() + ".exr", exr);
  ImageWriteOptions png;
  png.exposure = exposure;
  writeImage(image, stem.string() + ".png", png);
}

std::string studyPageHtml(const std::string& title, const std::string& table_html,
                          const std::vector<std::string>& notes,
                          const std::vector<std::string>& images) {
  std::string html = fmt::format(
      "<!doctype html><html><head><meta charset=\"utf-8\"><title>{0}</title><style>body{{font-"
      "family:sans-serif}}table{{border-collapse:collapse}}td,th{{border:1px solid "
      "#ccc;padding:3px 6px}}img{{image-rendering:pixelated;width:320px}}</style></head><body>"
      "<h1>{0}</h1>{1}",
      escapeHtml(title), table_html);
  for (const std::string& note : notes) html += "<p>" + escapeHtml(note) + "</p>";
  html += "<h2>Images</h2><p>";
  for (const std::string& name : images)
    html += fmt::format(
        "<figure style=\"display:inline-block\"><img src=\"images/{0}.png\">"
        "<figcaption>{0}</figcaption></figure>",
        escapeHtml(name));
  return html + "</p></body></html>\n";
}

void writeStudyReport(const std::filesystem::path& dir, const StudyReportFiles& f) {
  std::filesystem::create_directories(dir / "images");
  const float exposure = autoExposure(*f.reference);
  std::vector<std::string> names{"reference"};
  writeImagePair(*f.reference, dir / "images" / "reference", exposure);
  for (const auto& [name, image] : f.images) {
    names.push_back(name);
    writeImagePair(*image, dir / "images" / name, exposure);
  }
  writeTextAtomically(dir / "report.json", f.json);
  writeTextAtomically(dir / "report.md", f.markdown);
  writeTextAtomically(dir / "report.html", studyPageHtml(f.title, f.table_html, f.notes, names));
}

}  // namespace proxyvis
