/**
 * @file
 * report.html: one self-contained page per run (the `report' outputs of
 * both pipelines).
 *
 * The page is a static template (contrib/report/, installed next to the
 * scripts in `share/masonry/scripts/report/`) filled with the run's data
 * as JSON and plotly.js, the JavaScript library of Debian's python3-plotly
 * (its 8.6 MB `plotly.js`, stored gzip-compressed at build time in
 * `report/plotly.js.gz` and unpacked by the browser, so that a page is
 * about 2.5 MB plus its data). Nothing is fetched when the page is
 * viewed: it opens offline in any browser that has `DecompressionStream`
 * (Chrome and Edge 80, Firefox 113, Safari 16.4 and later). The data is
 * written by the C++ output (rigid blocks) or by the installed script
 * wallette_report.py from the run's files; the page's script draws it.
 */
#ifndef masonry_core_report_page_h
#define masonry_core_report_page_h

#include <string>

namespace masonry
{
  /**
   * Write the report page @p path (a full path): the template filled with
   * @p title, the page script `report/<kind>.js` (with the shared
   * `report/common.js`) and @p data, the JSON text it draws. Written under
   * a temporary name in the same directory and renamed when complete (a
   * page is whole or absent). Returns "" or why it was not written, in one
   * line (a part not found and the package that brings it); a failed write
   * (a full disk, ...) throws "cannot write 'PATH': REASON".
   */
  std::string
  write_report_page(const std::string &path,
                    const std::string &title,
                    const std::string &kind,
                    const std::string &data);
} // namespace masonry

#endif
