// A box with sharp edges and corners: three faces meet at each corner.
cube([60, 40, 30], center = true);
