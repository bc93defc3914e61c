// A die: a cube with rounded-off corners and spherical dimples (one to six).
s = 40;
pip = 3.5;
module dimples(points) {
    for (p = points) translate([p[0], p[1], s / 2]) sphere(r = pip, $fn = 20);
}
difference() {
    intersection() {
        cube(s, center = true);
        sphere(r = 0.8 * s, $fn = 64);
    }
    dimples([[0, 0]]);                                              // 1 on top
    rotate([180, 0, 0]) dimples([[-10, -10], [-10, 0], [-10, 10], [10, -10], [10, 0], [10, 10]]);  // 6 below
    rotate([90, 0, 0]) dimples([[-10, -10], [10, 10]]);             // 2
    rotate([-90, 0, 0]) dimples([[-10, -10], [0, 0], [10, 10], [-10, 10], [10, -10]]);  // 5
    rotate([0, 90, 0]) dimples([[-10, -10], [0, 0], [10, 10]]);     // 3
    rotate([0, -90, 0]) dimples([[-10, -10], [10, 10], [-10, 10], [10, -10]]);  // 4
}
