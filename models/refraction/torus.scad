// A smooth surface with a concave part: its inner side faces the hole.
rotate_extrude($fn = 96) translate([20, 0, 0]) circle(r = 9, $fn = 48);
