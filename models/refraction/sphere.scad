// A smooth convex body: the unit sphere, finely tessellated.
sphere(r = 1, $fn = 96);
