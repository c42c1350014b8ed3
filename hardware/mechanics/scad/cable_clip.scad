// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: CERN-OHL-S-2.0
//
// Cable clip: an open ring that snaps over the motor and encoder cable bundle, with a tab for an M3
// screw into the neck base or the head frame. Print flat; remix the bundle size for your harness.

bundle_d = 8;         // cable bundle diameter, mm
wall = 1.8;
width = 6;            // along the cable
opening = 0.7;        // snap opening as a fraction of the bundle diameter
screw_d = 3.4;
tab = 10;
$fn = 72;

outer = bundle_d + 2 * wall;

difference() {
    union() {
        cylinder(d = outer, h = width);
        translate([-outer / 2 - tab, -wall, 0]) cube([tab + outer / 2, 2 * wall, width]);
    }
    translate([0, 0, -1]) cylinder(d = bundle_d, h = width + 2);
    translate([0, -bundle_d * opening / 2, -1]) cube([outer, bundle_d * opening, width + 2]);
    translate([-outer / 2 - tab / 2, 0, width / 2]) rotate([90, 0, 0])
        cylinder(d = screw_d, h = 4 * wall, center = true);
}
