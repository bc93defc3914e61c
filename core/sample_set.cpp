#include "core/sample_set.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <iterator>
#include <span>
#include <streambuf>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/fingerprint.h"
#include "core/input_file.h"
#include "core/lazy.h"
#include "core/limits.h"

static_assert(std::endian::native == std::endian::little, "the sample file is little endian; add byte swapping");

namespace lucent {
namespace {

constexpr char kMagic[8] = {'L', 'U', 'C', 'E', 'N', 'T', 'S', 'F'};

class Writer {
public:
    template <class T>
    void put(const T& v) {
        const auto* p = reinterpret_cast<const char*>(&v);
        bytes.insert(bytes.end(), p, p + sizeof(T));
    }
    template <class T>
    void putArray(const std::vector<T>& v) {
        const auto* p = reinterpret_cast<const char*>(v.data());
        bytes.insert(bytes.end(), p, p + v.size() * sizeof(T));
    }
    std::vector<char> bytes;
};

// Reads the file's fields in order, each straight into its own storage, and
// hashes them on the way: one buffer copied out again touched every byte twice
// and took twice as long. size is the whole file's, checked
// against the counts before anything they claim is allocated.
class Reader {
public:
    Reader(std::istream& in, uint64_t size, const std::string& file) : in_(in), size_(size), file_(file) {}
    template <class T>
    T get() {
        T v;
        read(&v, sizeof(T));
        return v;
    }
    template <class T>
    std::vector<T> getArray(size_t count) {
        need(count * sizeof(T));
        std::vector<T> v(count);
        read(v.data(), count * sizeof(T));
        return v;
    }
    // Reads count values in pieces, hashed like the rest, and hands each piece
    // to visit(std::span<const T>) without keeping it.
    template <class T, class Visit>
    void skimArray(size_t count, Visit&& visit) {
        need(count * sizeof(T));
        std::vector<T> piece(std::min<size_t>(count, (size_t(1) << 20) / sizeof(T)));
        for (size_t done = 0; done < count;) {
            const size_t n = std::min(piece.size(), count - done);
            read(piece.data(), n * sizeof(T));
            visit(std::span<const T>(piece.data(), n));
            done += n;
        }
    }
    uint64_t offset() const { return offset_; }
    uint64_t size() const { return size_; }
    uint64_t checksum() const { return checksum_.value(); }  // of the bytes read so far

private:
    void need(uint64_t n) const {
        if (n > size_ - offset_) throw Error(file_, "sample file is truncated");
    }
    void read(void* to, uint64_t n) {
        need(n);
        if (n == 0) return;  // to may be null
        in_.read(static_cast<char*>(to), std::streamsize(n));
        if (uint64_t(in_.gcount()) != n) throw Error(file_, "sample file changed size while being read");
        checksum_.addBytes(to, n);
        offset_ += n;
    }
    std::istream& in_;
    uint64_t size_;
    const std::string& file_;
    uint64_t offset_ = 0;
    Fingerprint checksum_;
};

// Bytes in memory as a stream, without a copy.
class MemoryBuffer : public std::streambuf {
public:
    explicit MemoryBuffer(std::span<const char> bytes) {
        char* begin = const_cast<char*>(bytes.data());  // only read: the get area
        setg(begin, begin, begin + bytes.size());
    }
};

// file: the sample file r reads, whose coefficients are left in it; empty: r
// reads bytes in memory, and the coefficients are copied out.
SampleSet parse(Reader& r, const std::string& name, const std::filesystem::path& file);

template <class T>
bool allFinite(const std::vector<T>& v) {
    const auto* p = reinterpret_cast<const float*>(v.data());
    const size_t n = v.size() * sizeof(T) / sizeof(float);
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(p[i])) return false;
    return true;
}

}  // namespace

void writeSampleFile(const std::filesystem::path& file, const SampleSet& s) {
    Writer w;
    w.bytes.insert(w.bytes.end(), kMagic, kMagic + 8);
    w.put(kSampleFileVersion);
    w.put(uint64_t(s.size()));
    w.put(s.shOrder);
    w.put(s.channels);
    w.put(s.sceneFingerprint);
    for (int i = 0; i < 3; ++i) w.put(float(s.bounds.min[i]));
    for (int i = 0; i < 3; ++i) w.put(float(s.bounds.max[i]));
    const SampleParameters& p = s.parameters;
    w.put(p.seed);
    w.put(p.heuristicDirections);
    w.put(p.projectionDirections);
    w.put(p.layerCount);
    w.put(p.layerSpacing);
    w.put(p.meanRadius);
    w.put(p.widthFactor);
    w.put(p.cullEpsilon);
    w.put(uint32_t(p.scheme));
    w.put(p.regionAxis);
    w.put(p.placementScale);
    w.putArray(s.positions);
    w.putArray(s.radii);
    w.putArray(s.widths);
    w.putArray(s.weights);
    w.putArray(s.extinction);
    w.putArray(s.region);
    w.putArray(s.image);
    w.putArray(s.boundary);
    w.putArray(s.coefficients());
    w.putArray(s.truncationError);
    // The mesh in single precision: what it was read as (OpenMesh's points are floats).
    w.put(uint64_t(s.mesh.positions.size()));
    w.put(uint64_t(s.mesh.triangles.size()));
    for (const Vec3& p : s.mesh.positions) w.put(glm::vec3(p));
    w.putArray(s.mesh.triangles);
    Fingerprint checksum;
    checksum.addBytes(w.bytes.data(), w.bytes.size());
    w.put(checksum.value());

    AtomicFile out(file);
    out.stream().write(w.bytes.data(), std::streamsize(w.bytes.size()));
    out.commit();
}

SampleSet readSampleFile(const std::filesystem::path& file) {
    const std::string name = file.string();
    const uint64_t size = regularFileSize(file, "sample file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(name, "cannot open sample file");
    Reader r(in, size, name);
    return parse(r, name, file);
}

SampleSet parseSampleFile(std::span<const char> bytes, const std::string& name) {
    MemoryBuffer buffer(bytes);
    std::istream in(&buffer);
    Reader r(in, bytes.size(), name);
    return parse(r, name, {});
}

// Opened again when asked for, not kept open: a scene may hold more objects than
// a process may open files.
class CoefficientsInFile {
public:
    CoefficientsInFile(std::filesystem::path file, uint64_t offset, size_t count, uint64_t digest)
        : file_(std::move(file)), offset_(offset), count_(count), digest_(digest) {}
    const std::vector<float>& get() const {
        return values_.get([this] {
            const std::string name = file_.string();
            const Error changed(name, "sample file changed since it was read (run the command again)");
            // The size first: nothing is allocated for a file that no longer holds them.
            if (regularFileSize(file_, "sample file") < offset_ + count_ * sizeof(float)) throw changed;
            std::ifstream in(file_, std::ios::binary);
            if (!in) throw Error(name, "cannot open sample file");
            std::vector<float> v(count_);
            in.seekg(std::streamoff(offset_));
            in.read(reinterpret_cast<char*>(v.data()), std::streamsize(count_ * sizeof(float)));
            if (!in || uint64_t(in.gcount()) != count_ * sizeof(float)) throw changed;
            Fingerprint digest;
            digest.addBytes(v.data(), count_ * sizeof(float));
            if (digest.value() != digest_) throw changed;
            return v;
        });
    }

private:
    std::filesystem::path file_;
    uint64_t offset_;
    size_t count_;
    uint64_t digest_;  // of the coefficients' bytes when the file was read and checked
    Lazy<std::vector<float>> values_;
};

const std::vector<float>& SampleSet::coefficients() const {
    return sh.empty() && coefficientsInFile ? coefficientsInFile->get() : sh;
}

namespace {

SampleSet parse(Reader& r, const std::string& name, const std::filesystem::path& file) {
    std::array<char, 8> magic{};
    if (r.size() >= 8) magic = r.get<std::array<char, 8>>();
    if (std::memcmp(magic.data(), kMagic, 8) != 0) throw Error(name, "not a Lucent sample file (wrong magic number)");
    const uint32_t version = r.get<uint32_t>();
    if (version != kSampleFileVersion)
        throw Error(name, "sample file version " + std::to_string(version) + " is not supported (expected " +
                              std::to_string(kSampleFileVersion) + "); run lucent preprocess again");
    SampleSet s;
    const uint64_t count = r.get<uint64_t>();
    s.shOrder = r.get<uint32_t>();
    s.channels = r.get<uint32_t>();
    if (s.shOrder < 1 || s.shOrder > kMaxSampleShOrder)
        throw Error(name, "SH order " + std::to_string(s.shOrder) + " is out of range (1 to " +
                              std::to_string(kMaxSampleShOrder) + ")");
    if (s.channels != 1 && s.channels != 3) throw Error(name, "channel count must be 1 or 3");
    s.sceneFingerprint = r.get<uint64_t>();
    float b[6];
    for (float& v : b) v = r.get<float>();
    s.bounds.min = Vec3(b[0], b[1], b[2]);
    s.bounds.max = Vec3(b[3], b[4], b[5]);
    SampleParameters& p = s.parameters;
    p.seed = r.get<uint64_t>();
    p.heuristicDirections = r.get<uint32_t>();
    p.projectionDirections = r.get<uint32_t>();
    p.layerCount = r.get<uint32_t>();
    p.layerSpacing = r.get<float>();
    p.meanRadius = r.get<float>();
    p.widthFactor = r.get<float>();
    p.cullEpsilon = r.get<float>();
    // The header's numbers: finite bounds, and finite, non-negative lengths.
    for (const float v : b)
        if (!std::isfinite(v)) throw Error(name, "sample file header has non-finite bounds");
    for (const float v : {p.layerSpacing, p.meanRadius, p.widthFactor, p.cullEpsilon})
        if (!std::isfinite(v) || v < 0.0f)
            throw Error(name, "sample file header holds a negative or non-finite parameter");
    const uint32_t scheme = r.get<uint32_t>();
    if (scheme > uint32_t(SampleScheme::OpticallyThick))
        throw Error(name, "unknown sample scheme " + std::to_string(scheme));
    p.scheme = SampleScheme(scheme);
    p.regionAxis = r.get<uint32_t>();
    if (p.regionAxis > kNoRegionAxis)
        throw Error(name, "region axis " + std::to_string(p.regionAxis) + " is out of range");
    p.placementScale = r.get<float>();
    if (!(std::isfinite(p.placementScale) && p.placementScale > 0.0f))
        throw Error(name, "sample file header holds a placement scale that is not positive and finite");
    // The counts fix the size: check it before allocating anything they claim.
    const uint64_t perSample = sizeof(glm::vec3) * 3 + sizeof(glm::vec2) + sizeof(BoundaryBall) + sizeof(float) * 4 +
                               sizeof(float) * s.coefficientsPerSample();
    const uint64_t expected = r.offset() + count * perSample + 3 * sizeof(uint64_t);  // and the mesh's
    auto sizeMismatch = [&](uint64_t need, const char* atLeast) {
        return Error(name, "sample file holds " + std::to_string(r.size()) + " bytes but its counts need " + atLeast +
                               std::to_string(need) + " (truncated or corrupted)");
    };
    if (count > (uint64_t(1) << 40) / perSample || r.size() < expected) throw sizeMismatch(expected, "at least ");
    s.positions = r.getArray<glm::vec3>(count);
    s.radii = r.getArray<float>(count);
    s.widths = r.getArray<float>(count);
    s.weights = r.getArray<float>(count);
    s.extinction = r.getArray<glm::vec3>(count);
    s.region = r.getArray<glm::vec2>(count);
    s.image = r.getArray<glm::vec3>(count);
    s.boundary = r.getArray<BoundaryBall>(count);
    bool finiteCoefficients = true;
    const size_t coefficients = count * s.coefficientsPerSample();
    if (file.empty()) {
        s.sh = r.getArray<float>(coefficients);
        finiteCoefficients = allFinite(s.sh);
    } else {
        const uint64_t offset = r.offset();
        Fingerprint digest;
        r.skimArray<float>(coefficients, [&](std::span<const float> piece) {
            digest.addBytes(piece.data(), piece.size_bytes());
            for (float c : piece) finiteCoefficients = finiteCoefficients && std::isfinite(c);
        });
        s.coefficientsInFile = std::make_shared<CoefficientsInFile>(file, offset, coefficients, digest.value());
    }
    s.truncationError = r.getArray<float>(count);
    const uint64_t vertices = r.get<uint64_t>(), triangles = r.get<uint64_t>();
    const uint64_t meshBytes = r.size() - r.offset() - sizeof(uint64_t);
    constexpr uint64_t kCorner = 3 * sizeof(float);
    if (vertices > meshBytes / kCorner || triangles > meshBytes / kCorner ||
        kCorner * (vertices + triangles) != meshBytes)
        throw sizeMismatch(
            r.offset() + kCorner * (std::min(vertices, meshBytes) + std::min(triangles, meshBytes)) + sizeof(uint64_t),
            "");
    const std::vector<glm::vec3> meshPositions = r.getArray<glm::vec3>(vertices);
    s.mesh.triangles = r.getArray<std::array<uint32_t, 3>>(triangles);
    const uint64_t payload = r.checksum();
    const uint64_t stored = r.get<uint64_t>();
    if (payload != stored) throw Error(name, "sample file checksum does not match (corrupted)");
    if (!allFinite(s.positions) || !allFinite(s.radii) || !allFinite(s.widths) || !allFinite(s.weights) ||
        !allFinite(s.extinction) || !allFinite(s.region) || !allFinite(s.image) || !allFinite(s.boundary) ||
        !finiteCoefficients || !allFinite(s.truncationError))
        throw Error(name, "sample file holds a non-finite value");
    // The mesh: what every index and coordinate must be for the passes and ray
    // casters that take it (its closedness was checked when it was read).
    if ((vertices == 0) != (triangles == 0)) throw Error(name, "sample file holds a mesh without vertices or faces");
    s.mesh.positions.reserve(vertices);
    for (const glm::vec3& p : meshPositions) {
        if (!isFinite(Vec3(p)) || std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate)
            throw Error(name, "sample file holds a mesh vertex that is not finite or lies beyond 1e13");
        s.mesh.positions.push_back(Vec3(p));
    }
    for (const auto& t : s.mesh.triangles)
        if (t[0] >= vertices || t[1] >= vertices || t[2] >= vertices)
            throw Error(name, "sample file holds a mesh face with a vertex index out of range");
    if (vertices > 0 && !(s.mesh.bounds().diagonal() >= kMinObjectSize))
        throw Error(name, "sample file holds a mesh smaller than 1e-9 across");
    for (size_t i = 0; i < count; ++i) {
        if (!(s.widths[i] > 0.0f) || !(s.radii[i] > 0.0f))
            throw Error(name, "sample " + std::to_string(i) + " has a non-positive width");
        if (s.weights[i] < 0.0f || glm::any(glm::lessThan(s.extinction[i], glm::vec3(0.0f))))
            throw Error(name, "sample " + std::to_string(i) + " has a negative coefficient");
        if (!(s.region[i].x <= s.region[i].y))
            throw Error(name, "sample " + std::to_string(i) + " has an empty region");
        const BoundaryBall& b = s.boundary[i];
        if (b.valid() && (std::abs(glm::length(b.normal) - 1.0f) > 1e-3f || b.curvature < 0.0f ||
                          b.curvature * b.depth > 1.0f || !(b.share >= 0.0f && b.share <= 1.0f)))
            throw Error(name, "sample " + std::to_string(i) + " has an invalid boundary ball");
    }
    return s;
}

}  // namespace

}  // namespace lucent
