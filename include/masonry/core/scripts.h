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
 * and runs it with `/usr/bin/python3`, or calls run_script(), which does
 * both. A new script is a new file in
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

  /**
   * Run the installed script @p name (find_script()) with `/usr/bin/python3`
   * and @p arguments (each passed as one argument), its output discarded.
   * Returns "" if it ran and exited with 0, otherwise why not, in the words
   * of the cause: "NAME not found", "/usr/bin/python3 not found", "NAME
   * needs python3-matplotlib" (a module that is not installed, with its
   * Debian package), or "NAME failed (the script's last error line)".
   *
   * @p outputs are the files the script writes: if it fails, they are
   * removed, so that a picture is whole or absent. If it failed because a
   * file could not be written (a full disk, a file-size limit, an I/O
   * error), that is no reason to go on: run_script() throws an ExcMessage
   * "cannot write 'FILE': REASON" naming the first of @p outputs.
   *
   * The caller names the files the script wrote (OutputDirectory::file())
   * only on success: a file named but not written makes the run `failed'.
   */
  std::string
  run_script(const std::string              &name,
             const std::vector<std::string> &arguments,
             const std::vector<std::string> &outputs = {});
} // namespace masonry

#endif
