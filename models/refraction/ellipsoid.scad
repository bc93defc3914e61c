// A smooth convex body with three different curvatures.
scale([30, 18, 22]) sphere(r = 1, $fn = 96);
