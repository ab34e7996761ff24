// The plotting scripts are found through masonry::find_script() in the
// build tree's share/masonry/scripts/ (next to libmasonry, since a test
// executable lives elsewhere), not in the source tree; an unknown script
// gives an empty path.
#include <masonry/core/scripts.h>

#include <filesystem>
#include <iostream>

int
main()
{
  for (const std::string name : {"vault_picture.py", "adaptation_plot.py"})
    {
      const std::filesystem::path script = masonry::find_script(name);
      const std::filesystem::path dir    = script.parent_path();
      std::cout << name << ": "
                << (std::filesystem::is_regular_file(script) ? "found" :
                                                               "MISSING")
                << " in " << dir.parent_path().parent_path().filename().string()
                << "/" << dir.parent_path().filename().string() << "/"
                << dir.filename().string() << ", next to libmasonry: "
                << (std::filesystem::exists(dir.parent_path().parent_path() /
                                            "../libmasonry.so") ?
                      "yes" :
                      "no")
                << "\n";
    }
  std::cout << "no_such_script.py: '"
            << masonry::find_script("no_such_script.py") << "'\n";
}
