// Extruded letters L, U and X standing on a thin base that joins them into one solid.
module letterL() polygon([[0, 0], [18, 0], [18, 6], [6, 6], [6, 30], [0, 30]]);
module letterU() polygon([[0, 0], [20, 0], [20, 30], [14, 30], [14, 6], [6, 6], [6, 30], [0, 30]]);
module letterX() union() {
    polygon([[0, 0], [6, 0], [22, 30], [16, 30]]);
    polygon([[16, 0], [22, 0], [6, 30], [0, 30]]);
}
union() {
    translate([-36, -2, -15]) cube([76, 12, 4]);  // overlaps the letters by 1
    rotate([90, 0, 0]) translate([0, 0, -10]) linear_extrude(height = 10) {
        translate([-34, -12]) letterL();
        translate([-11, -12]) letterU();
        translate([14, -12]) letterX();
    }
}
