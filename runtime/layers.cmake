# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# The runtime's layers, lowest first: "<library> <root folder under runtime/> <layers it links...>".
# Each layer is one static library built from <root>/src, whose include path is <root>/include
# plus the include folders of the layers it links, and nothing else: a header of a higher layer
# is not found, so including one fails the build. Read by runtime/CMakeLists.txt, the fuzz
# build and the layering test (tests/layering).
set(ROBOGENE_LAYERS
  "base base"
  "bottle bottle base"
  "carriers carriers bottle"
  "ports ports carriers"
  "nameserver nameserver ports"
  "devices devices ports")
