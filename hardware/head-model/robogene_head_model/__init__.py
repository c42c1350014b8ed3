# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: CERN-OHL-S-2.0
"""The head model that the CAD and the code generator share, read from hardware/head-parameters.yaml:

params        the parameter file, checked, with errors naming the key path or line (params.load)
joint_config  the control board's joints and limits, per chain joint its motor, reduction and encoders
drive_limits  per chain joint the torque and speed its motor and gearhead deliver at the joint

It needs PyYAML only, so the generator imports it without the CAD's dependencies."""
