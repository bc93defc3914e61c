// The same box with its edges rounded (radius 6): the hull of eight spheres.
r = 6;
hull() for (x = [-24, 24], y = [-14, 14], z = [-9, 9]) translate([x, y, z]) sphere(r = r, $fn = 32);
