// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// Reads an ini file with the runtime's own Property parser and prints every group and key as
// `group key value...` lines (values in bottle text form), so the tests check what a driver sees.
#include <iostream>

#include "robogene/dev/property.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: property_tool FILE.ini\n";
    return 2;
  }
  try {
    const auto p = robogene::dev::Property::from_ini_file(argv[1]);
    const auto all = p.to_bottle();
    std::cout << all.to_text() << "\n";
  } catch (const robogene::Error& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
