// A plate with six cylindrical through-holes.
difference() {
    cube([80, 60, 12], center = true);
    for (x = [-25, 0, 25], y = [-15, 15]) translate([x, y, 0]) cylinder(d = 12, h = 20, center = true, $fn = 40);
}
