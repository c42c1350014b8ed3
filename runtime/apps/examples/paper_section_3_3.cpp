// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// The paper's section 3.3 as a program: open a control board through PolyDriver, view
// IPositionControl and IVelocityControl, move joint 0 to 40 deg and joint 1 at 5 deg/s, and
// print the encoders as they follow. Which device is opened comes only from the command line:
//   paper_section_3_3                                    test_motor in this process
//   paper_section_3_3 --device remote_controlboard --remote /motors --local /paper
//                                                        the one `robogene dev` serves as /motors
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "robogene/dev/generated/interfaces.hpp"
#include "robogene/dev/poly_driver.hpp"
#include "robogene/error.hpp"

using namespace robogene::dev;

int main(int argc, char** argv) {
  Property config;
  try {
    config = Property::from_command_line(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const robogene::Error& e) {
    std::fprintf(stderr, "paper_section_3_3: %s\n", e.what());
    return 2;
  }
  if (!config.check("device")) config.put("device", robogene::Value::string("test_motor"));
  const double seconds = config.get_float("seconds", 2.0, 0.0, 3600.0);

  PolyDriver device;
  if (!device.open(config)) {
    std::fprintf(stderr, "paper_section_3_3: %s\n", device.last_error().c_str());
    return 1;
  }

  // Section 3.3, as written.
  IPositionControl* ipos = 0;
  device.view(ipos);
  IVelocityControl* ivel = 0;
  device.view(ivel);
  IEncoders* ienc = 0;
  device.view(ienc);
  if (!ipos || !ivel || !ienc) {
    std::fprintf(stderr, "paper_section_3_3: the device is not a control board\n");
    return 1;
  }
  ipos->setRefAcceleration(0, 100);
  ipos->setRefSpeed(0, 5);
  ipos->positionMove(0, 40);

  ivel->setRefAcceleration(1, 100);
  ivel->velocityMove(1, 5);

  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<double> encs;
    if (!ienc->getEncoders(encs)) {
      std::fprintf(stderr, "paper_section_3_3: cannot read the encoders\n");
      return 1;
    }
    std::printf("t=%.2f s  joint 0: %7.3f deg  joint 1: %7.3f deg\n", t, encs.at(0), encs.at(1));
    std::fflush(stdout);
    if (t >= seconds) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  device.close();  // joint 1 keeps its velocity, as in the paper
  return 0;
}
