// A convex body with a sharp rim: two spherical caps, their normals 106 degrees apart where they meet.
intersection() {
    translate([0, 0, -40]) sphere(r = 50, $fn = 128);
    translate([0, 0, 40]) sphere(r = 50, $fn = 128);
}
