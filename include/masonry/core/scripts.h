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
   * One script to run: the installed script @p script (a name for
   * find_script()) with @p arguments, each passed as one argument. If the
   * script writes one file, @p output is its full path and the argument
   * "{output}" stands for it: the script then writes a temporary name in
   * the same directory, renamed to @p output only when the script
   * succeeded (a picture is whole or absent).
   */
  struct ScriptJob
  {
    /** The script's name, e.g. "vault_picture.py". */
    std::string script;
    /** Its arguments ("{output}": the temporary name of @p output). */
    std::vector<std::string> arguments;
    /** The file it writes, or "". */
    std::string output;
  };

  /**
   * Run @p jobs in one `/usr/bin/python3` process (the installed runner
   * masonry_scripts.py runs each script as `__main__`, so Python starts
   * and matplotlib is imported once), in order. Returns per job "" if it
   * ran and exited with 0, otherwise why not, in one line: "NAME not
   * found", "/usr/bin/python3 not found", or the real cause the runner
   * found (a missing Debian package, a full disk, the script's exception
   * and line). The caller names the files a script wrote
   * (OutputDirectory::file()) only on success: a file named but not
   * written makes the run `failed'.
   *
   * A script that failed because a file could not be written (a full
   * disk, a file-size limit, an I/O error) is no reason to go on:
   * run_scripts() then throws an ExcMessage "cannot write 'FILE': REASON"
   * naming the job's output (or script).
   */
  std::vector<std::string>
  run_scripts(const std::vector<ScriptJob> &jobs);

  /**
   * Run the installed script @p name with @p arguments: run_scripts() of
   * one job. @p outputs are the files it writes by names of its own: they
   * are removed if it fails, so that they are whole or absent. Returns ""
   * or why it failed.
   */
  std::string
  run_script(const std::string              &name,
             const std::vector<std::string> &arguments,
             const std::vector<std::string> &outputs = {});
} // namespace masonry

#endif
