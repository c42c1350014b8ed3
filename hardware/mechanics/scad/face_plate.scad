// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: CERN-OHL-S-2.0
//
// Face plate: the printed face screwed to the front edges of the head's side plates, with openings the
// eyes look through over their whole pan and tilt range. The most remixed part of a head: make it yours.
// Modelled lying flat (print orientation); on the head its x is the head's y and its y the head's z.

width = 132;          // across the head = 2 * floor half_width
height = 112;         // side plate height
thickness = 3;
eye_y = 82;           // eye height above the head floor
baseline = 68;
eye_w = 46;           // opening width and height: they frame a camera's view (66 x 41 degrees) looking
eye_h = 36;           // straight ahead from 37 mm behind the plate; a turned eye sees partly past the edge
edge_inset = 3;       // screw holes on the middle of the side plates' front edges
screw_z = [20, 92];   // their heights above the head floor
screw_d = 3.4;
corner_r = 10;
$fn = 64;

module rounded_rect(w, h, r) {
    offset(r = r) offset(delta = -r) square([w, h], center = true);
}

linear_extrude(height = thickness) difference() {
    translate([0, height / 2]) rounded_rect(width, height, corner_r);
    for (s = [-1, 1]) translate([s * baseline / 2, eye_y]) scale([eye_w / eye_h, 1]) circle(d = eye_h);
    // mouth grille: ventilation for the motors
    for (k = [-3 : 3]) translate([k * 9, 28]) rounded_rect(5, 16, 2.4);
    for (sx = [-1, 1], yy = screw_z) translate([sx * (width / 2 - edge_inset), yy]) circle(d = screw_d);
}
