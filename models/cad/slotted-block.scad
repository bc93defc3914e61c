// A block with a slot cut across its top and a rectangular pocket in one side.
difference() {
    cube([60, 40, 30], center = true);
    translate([0, 0, 8]) cube([12, 50, 20], center = true);
    translate([20, -20, -4]) cube([10, 16, 10], center = true);
}
