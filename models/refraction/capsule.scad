// A smooth convex body, straight along its axis: two hemispheres joined by a cylinder.
hull() for (x = [-20, 20]) translate([x, 0, 0]) sphere(r = 14, $fn = 64);
