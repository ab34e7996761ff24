// Bad input of the geometry models: each error names the entry.

#include <fstream>

#include "geometry_common.h"

using namespace masonry;

namespace
{
  void
  expect(const std::string &what,
         const std::string &model,
         const std::string &entries,
         const std::string &entry_path,
         const std::string &common = "")
  {
    const std::string message =
      test::error_of([&]() { test::create(model, entries, common); });
    test::check(message.find("'" + entry_path + "'") != std::string::npos,
                what + " names " + entry_path,
                "message: " + message);
    std::cout << "  " << message << std::endl;
  }
} // namespace

int
main()
{
  expect("negative span", "arch", "set Span = -4", "Geometry model/Arch/Span");
  expect("zero rise", "arch", "set Rise = 0", "Geometry model/Arch/Rise");
  expect("pointed rise <= span/2",
         "barrel vault",
         "set Shape = pointed\nset Span = 6\nset Rise = 3",
         "Geometry model/Barrel vault/Rise");
  expect("circular rise > span/2",
         "barrel vault",
         "set Shape = circular\nset Span = 6\nset Rise = 3.5",
         "Geometry model/Barrel vault/Rise");
  expect("intrados with a varying thickness",
         "barrel vault",
         "set Span and rise of = intrados",
         "Geometry model/Barrel vault/Span and rise of",
         "set Thickness = 0.3 + 0.01*z");
  expect("extrados thinner than the thickness (circular)",
         "arch",
         "set Span = 1\nset Rise = 0.5\nset Span and rise of = extrados",
         "Geometry model/Arch/Span and rise of",
         "set Thickness = 0.6");
  expect("extrados thinner than the thickness (pointed)",
         "barrel vault",
         "set Span = 0.6\nset Rise = 0.8\nset Span and rise of = extrados",
         "Geometry model/Barrel vault/Span and rise of",
         "set Thickness = 0.35");
  expect("negative length",
         "barrel vault",
         "set Length = -1",
         "Geometry model/Barrel vault/Length");
  expect("negative span x",
         "cross vault",
         "set Span x = -6",
         "Geometry model/Cross vault/Span x");
  expect("zero span y",
         "cross vault",
         "set Span y = 0",
         "Geometry model/Cross vault/Span y");
  expect("dome rise > span/2",
         "dome",
         "set Span = 10\nset Rise = 6",
         "Geometry model/Dome/Rise");
  expect("missing CAD file",
         "cad file",
         "set File name = does-not-exist.step",
         "Geometry model/Cad file/File name");
  std::ofstream("vault.txt") << "not CAD\n";
  expect("unknown CAD extension",
         "cad file",
         "set File name = vault.txt",
         "Geometry model/Cad file/File name");
  expect("non-positive thickness on the surface",
         "arch",
         "set Span = 4\nset Rise = 2",
         "Geometry model/Thickness",
         "set Thickness = 0.3 - 0.2*z");
  expect("unparsable thickness",
         "arch",
         "",
         "Geometry model/Thickness",
         "set Thickness = 0.3 + w");
  expect(
    "zero density", "arch", "", "Geometry model/Density", "set Density = 0");
  return test::failures();
}
