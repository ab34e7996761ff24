/**
 * @file
 * Helper scripts installed with masonry (the matplotlib plots of
 * contrib/plot/).
 *
 * `cmake --install` puts the Python files of contrib/plot/ into
 * `<prefix>/share/masonry/scripts/`, and the build tree holds a copy in
 * `<build>/share/masonry/scripts/` (made when CMake configures), so the same
 * lookup works for an installed and for a built masonry, and nothing points
 * into the source tree. A plugin that renders a picture calls
 *
 * @code
 * #include <masonry/core/scripts.h>
 * const std::string script = masonry::find_script("vault_picture.py");
 * if (script.empty()) ... // say that the picture is not written, and why
 * @endcode
 *
 * and runs it with `/usr/bin/python3`. A new script is a new file in
 * contrib/plot/; the build copies and installs it.
 */
#ifndef masonry_core_scripts_h
#define masonry_core_scripts_h

#include <string>
#include <vector>

namespace masonry
{
  /**
   * The folders searched for scripts, in this order: the environment
   * variable `MASONRY_SCRIPT_DIR` if set; for the folder of the running
   * executable and then the folder of the masonry library (an out-of-tree
   * program or a test linked against it), each `D`:
   * `D/../share/masonry/scripts` (installed: `<prefix>/bin`, `<prefix>/lib`)
   * and `D/share/masonry/scripts` (the build tree, where executable and
   * library live in the build folder itself). An executable and library
   * copied elsewhere find the scripts through `MASONRY_SCRIPT_DIR`.
   */
  std::vector<std::string>
  script_directories();

  /**
   * The full path of the installed script @p name (e.g.
   * `"vault_picture.py"`): the first of script_directories() that holds
   * it, or an empty string if none does.
   */
  std::string
  find_script(const std::string &name);
} // namespace masonry

#endif
