// Thin ribs (2 units thick, 16 high) meeting at right angles on a base plate.
union() {
    cube([64, 64, 4], center = true);
    for (x = [-24, -8, 8, 24]) translate([x, 0, 10]) cube([2, 64, 16], center = true);
    for (y = [-24, 0, 24]) translate([0, y, 10]) cube([64, 2, 16], center = true);
}
