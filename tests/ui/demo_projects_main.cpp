// CTest's ui_demo_projects fixture (tests/ui/CMakeLists.txt): replays the
// UI suites' demo projects (tests/ui/demo_project.h) once into the folder
// given, before the suites run; each suite's process copies them from there
// (ROCKFACE_TEST_DEMO_PROJECTS) instead of replaying them itself.
#include <exception>
#include <filesystem>
#include <iostream>

#include "tests/ui/demo_project.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: ui_demo_projects FOLDER (made afresh, holding the demo projects)\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  try {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const auto& recipe : rockface::test::demo_project_recipes()) {
      const auto project = rockface::test::make_demo_project(recipe, dir);
      std::cout << "replayed " << project.string() << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "ui_demo_projects: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
