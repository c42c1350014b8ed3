// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: CERN-OHL-S-2.0
//
// Camera spacer: a printed jig that holds both eye cups by their flat front faces, parallel and exactly
// one camera baseline apart, while the pan gearheads are tightened at zero. Remix freely.
// The build passes the head's numbers with -D (from hardware/head-parameters.yaml); defaults match it.

baseline = 68;        // camera baseline, mm
face_d = 29.5;        // diameter of the eye cup's flat front face
lens_d = 8.5;         // lens diameter: the lens looks through the jig
pocket = 3;           // pocket depth holding each face
thickness = 6;
clearance = 0.3;
$fn = 96;

length = baseline + face_d + 10;
width = face_d + 8;

difference() {
    translate([-length / 2, -width / 2, 0])
        cube([length, width, thickness]);
    for (s = [-1, 1]) {
        translate([s * baseline / 2, 0, thickness - pocket])
            cylinder(d = face_d + 2 * clearance, h = pocket + 1);
        translate([s * baseline / 2, 0, -1])
            cylinder(d = lens_d + 2, h = thickness + 2);
    }
    // finger notch to pull the jig off
    translate([0, width / 2, thickness])
        rotate([0, 90, 0]) cylinder(r = 4, h = 20, center = true);
}
