#include "core/transport_problem.h"

#include "core/input_file.h"
#include "core/internal/json_node.h"

namespace lucent {

namespace {

// Enough for the benchmarks and well inside the device budget checked later.
constexpr int kMaxCellsPerAxis = 1024;
constexpr double kMaxCells = double(1 << 24);
constexpr double kMaxCoefficient = 1e30;

Bounds3 parseBox(Node& n) {
    Bounds3 b;
    b.min = n.child("min").point();
    b.max = n.child("max").point();
    for (int a = 0; a < 3; ++a)
        if (!(b.min[a] < b.max[a])) n.fail("min must be below max on every axis");
    return b;
}

}  // namespace

TransportProblem parseTransportProblemText(const std::string& text, const std::filesystem::path& file) {
    const std::string name = file.string();
    const Json json = parseStrictJson(text, name);
    Node root(json, "", name);
    root.requireObject();
    TransportProblem p;
    p.file = file;

    Node domain = root.child("domain");
    domain.requireObject();
    p.domain = parseBox(domain);
    Node cells = domain.child("cells");
    if (cells.arraySize() != 3) cells.fail("must be an array of 3 integers");
    double total = 1.0;
    for (int a = 0; a < 3; ++a) total *= p.cells[a] = cells.element(a).integer(1, kMaxCellsPerAxis);
    if (total > kMaxCells) cells.fail("asks for more than 2^24 cells");
    domain.rejectUnknownKeys();

    if (root.has("boundary")) {
        Node boundary = root.child("boundary");
        boundary.requireObject();
        const char* faces[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};
        for (int f = 0; f < 6; ++f) {
            if (!boundary.has(faces[f])) continue;
            Node b = boundary.child(faces[f]);
            const std::string kind = b.string();
            if (kind != "vacuum" && kind != "reflective") b.fail("must be \"vacuum\" or \"reflective\"");
            p.reflective[f] = kind == "reflective";
        }
        boundary.rejectUnknownKeys();
    }

    Node regions = root.child("regions");
    for (size_t i = 0; i < regions.arraySize(); ++i) {
        Node r = regions.element(i);
        r.requireObject();
        TransportRegion region;
        region.box = parseBox(r);
        region.sigmaT = r.child("sigma_t").number(0.0, kMaxCoefficient);
        if (r.has("sigma_s")) region.sigmaS = r.child("sigma_s").number(0.0, kMaxCoefficient);
        if (region.sigmaS > region.sigmaT)
            r.fail("sigma_s (" + Node::fmt(region.sigmaS) + ") exceeds sigma_t (" + Node::fmt(region.sigmaT) + ")");
        if (r.has("g")) region.g = r.child("g").number(-0.999, 0.999);
        if (r.has("source")) region.source = r.child("source").number(0.0, kMaxCoefficient);
        r.rejectUnknownKeys();
        p.regions.push_back(region);
    }

    Node points = root.child("points");
    if (points.arraySize() == 0) points.fail("must hold at least one point");
    for (size_t i = 0; i < points.arraySize(); ++i) {
        Node pt = points.element(i);
        const Vec3 v = pt.point();
        if (!p.domain.contains(v)) pt.fail("lies outside the domain");
        p.points.push_back(v);
    }

    if (root.has("solver")) {
        Node s = root.child("solver");
        s.requireObject();
        if (s.has("directions")) p.directions = s.child("directions").integer(1, 100000);
        if (s.has("bands")) p.bands = s.child("bands").integer(1, 6);
        if (s.has("iterations")) p.maxIterations = s.child("iterations").integer(1, 100000);
        if (s.has("tolerance")) p.tolerance = s.child("tolerance").number(1e-9, 1.0);
        if (s.has("uncollided")) {
            Node u = s.child("uncollided");
            const std::string how = u.string();
            if (how == "auto")
                p.uncollided = TransportProblem::Uncollided::Auto;
            else if (how == "marched")
                p.uncollided = TransportProblem::Uncollided::Marched;
            else if (how == "swept")
                p.uncollided = TransportProblem::Uncollided::Swept;
            else
                u.fail("must be \"auto\", \"marched\" or \"swept\"");
        }
        s.rejectUnknownKeys();
    }
    root.rejectUnknownKeys();
    return p;
}

TransportProblem parseTransportProblem(const std::filesystem::path& file) {
    return parseTransportProblemText(readTextFile(file, "transport problem"), file);
}

}  // namespace lucent
