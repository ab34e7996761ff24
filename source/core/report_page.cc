#include <masonry/core/output_file.h>
#include <masonry/core/report_page.h>
#include <masonry/core/scripts.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace masonry
{
  namespace
  {
    /** The installed report file @p name, or "" (and @p why). */
    std::string
    read_part(const std::string &name, std::string &why)
    {
      const std::string path = find_script("report/" + name);
      if (path.empty())
        {
          why = "report/" + name + " not found" +
                (name == "plotly.js.gz" ?
                   " (install python3-plotly and re-run contrib/setup: the "
                   "build compresses its plotly.js)" :
                   "");
          return "";
        }
      std::ifstream      in(path, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      if (!in.good() && !in.eof())
        why = "cannot read " + path;
      return text.str();
    }

    /** @p bytes in base64 (RFC 4648). */
    std::string
    base64(const std::string &bytes)
    {
      static const char *alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::string  out;
      const auto   n = bytes.size();
      unsigned int k = 0;
      out.reserve(4 * ((n + 2) / 3));
      for (; k + 2 < n; k += 3)
        {
          const unsigned int v =
            (static_cast<unsigned char>(bytes[k]) << 16) |
            (static_cast<unsigned char>(bytes[k + 1]) << 8) |
            static_cast<unsigned char>(bytes[k + 2]);
          out += alphabet[(v >> 18) & 63];
          out += alphabet[(v >> 12) & 63];
          out += alphabet[(v >> 6) & 63];
          out += alphabet[v & 63];
        }
      if (k < n)
        {
          unsigned int v = static_cast<unsigned char>(bytes[k]) << 16;
          if (k + 1 < n)
            v |= static_cast<unsigned char>(bytes[k + 1]) << 8;
          out += alphabet[(v >> 18) & 63];
          out += alphabet[(v >> 12) & 63];
          out += k + 1 < n ? alphabet[(v >> 6) & 63] : '=';
          out += '=';
        }
      return out;
    }

    /** @p text for HTML text. */
    std::string
    html_escape(const std::string &text)
    {
      std::string out;
      for (const char c : text)
        out += c == '&' ? "&amp;" :
               c == '<' ? "&lt;" :
               c == '>' ? "&gt;" :
               c == '"' ? "&quot;" :
                          std::string(1, c);
      return out;
    }

    /**
     * JSON text made safe inside a script element: "</" only occurs in
     * strings, where "<\/" is the same string.
     */
    std::string
    script_safe(const std::string &json)
    {
      std::string out;
      out.reserve(json.size());
      for (std::size_t k = 0; k < json.size(); ++k)
        {
          out += json[k];
          if (json[k] == '<' && k + 1 < json.size() && json[k + 1] == '/')
            out += '\\';
        }
      return out;
    }
  } // namespace

  std::string
  write_report_page(const std::string &path,
                    const std::string &title,
                    const std::string &kind,
                    const std::string &data)
  {
    std::string       why;
    const std::string page   = read_part("page.html", why);
    const std::string style  = why.empty() ? read_part("report.css", why) : "";
    const std::string common = why.empty() ? read_part("common.js", why) : "";
    const std::string script = why.empty() ? read_part(kind + ".js", why) : "";
    const std::string plotly =
      why.empty() ? read_part("plotly.js.gz", why) : "";
    if (!why.empty())
      return why;

    // fill the template in one pass, so that no part is searched for the
    // markers of another
    const std::pair<const char *, std::string> parts[] = {
      {"{{TITLE}}", html_escape(title)},
      {"{{STYLE}}", style},
      {"{{DATA}}", script_safe(data)},
      {"{{PLOTLY}}", base64(plotly)},
      {"{{SCRIPT}}", common + "\n" + script}};
    // under a temporary name until whole; a failed write throws
    // "cannot write 'PATH': REASON" (OutputFile)
    OutputFile  out(path);
    std::size_t at = 0;
    while (at < page.size())
      {
        std::size_t        next = std::string::npos, length = 0;
        const std::string *text = nullptr;
        for (const auto &[marker, value] : parts)
          {
            const std::size_t found = page.find(marker, at);
            if (found < next)
              {
                next   = found;
                length = std::strlen(marker);
                text   = &value;
              }
          }
        out.write(page.data() + at,
                  (next == std::string::npos ? page.size() : next) - at);
        if (next == std::string::npos)
          break;
        out.write(text->data(), text->size());
        at = next + length;
      }
    out.close();
    return "";
  }
} // namespace masonry
