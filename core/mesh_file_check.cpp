#include "core/mesh_file_check.h"

#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace lucent {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem) {
    throw Error(file.string(), problem);
}

void checkCount(const std::filesystem::path& file, uint64_t count, const char* what) {
    if (count > kMaxMeshElements)
        fail(file, "header claims " + std::to_string(count) + " " + what + ", more than the " +
                       std::to_string(kMaxMeshElements) + " Lucent reads (docs/robustness.md)");
}

uint64_t parseCount(const std::filesystem::path& file, const std::string& word, const char* what) {
    uint64_t n = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), n);
    if (error != std::errc() || end != word.data() + word.size())
        fail(file, std::string("bad ") + what + " count '" + word + "'");
    return n;
}

// Bytes one PLY property takes at the least: its size in binary, a digit and a
// separator in ASCII.
uint64_t plyTypeSize(const std::filesystem::path& file, const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    fail(file, "unknown PLY property type '" + type + "'");
}

// The header, strictly: "ply", one format line, then only comment, obj_info,
// element and property lines up to end_header, each well formed. OpenMesh's own
// header parser crashes or loops forever on some malformed headers (fuzz/), so
// it only ever sees one that passed here.
void checkPly(const std::filesystem::path& file, uint64_t size) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    bool ascii = true, sawFormat = false;
    uint64_t headerBytes = 0, needed = 0, lineNumber = 0;
    struct Element {
        uint64_t count = 0, minBytes = 0;
    };
    std::vector<Element> elements;
    auto bad = [&](const std::string& problem) {
        fail(file, "PLY header line " + std::to_string(lineNumber) + ": " + problem);
    };
    while (std::getline(in, line)) {
        ++lineNumber;
        headerBytes += line.size() + 1;
        if (headerBytes > 65536) fail(file, "PLY header longer than 64 KiB");
        if (!line.empty() && line.back() == '\r') line.pop_back();
        for (const char c : line)
            if (static_cast<unsigned char>(c) < 0x20 && c != '\t') bad("control character in the header");
        std::istringstream words(line);
        std::string keyword, extra;
        words >> keyword;
        if (lineNumber == 1) {
            if (line != "ply") fail(file, "not a PLY file (the first line is not 'ply')");
        } else if (keyword == "format") {
            std::string format, version;
            words >> format >> version;
            if (sawFormat || (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian") ||
                version != "1.0" || (words >> extra))
                bad("expected one 'format ascii|binary_little_endian|binary_big_endian 1.0'");
            ascii = format == "ascii";
            sawFormat = true;
        } else if (keyword == "comment" || keyword == "obj_info") {
            continue;
        } else if (keyword == "element") {
            std::string name, count;
            if (!(words >> name >> count) || (words >> extra)) bad("expected 'element NAME COUNT'");
            elements.push_back({parseCount(file, count, "PLY element"), 0});
            checkCount(file, elements.back().count, name == "face" ? "faces" : "elements");
        } else if (keyword == "property") {
            if (elements.empty()) bad("property before any element");
            std::string type, name;
            if (!(words >> type)) bad("property without a type");
            if (type == "list") {
                std::string countType, itemType;
                if (!(words >> countType >> itemType >> name) || (words >> extra))
                    bad("expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
                plyTypeSize(file, itemType);
                type = countType;  // the list may be empty: its count is all it surely holds
            } else if (!(words >> name) || (words >> extra)) {
                bad("expected 'property TYPE NAME'");
            }
            elements.back().minBytes += ascii ? 2 : plyTypeSize(file, type);
        } else if (keyword == "end_header") {
            if (!sawFormat) bad("end_header before any format line");
            for (const Element& e : elements) needed += e.count * e.minBytes;
            if (needed > size - std::min(size, headerBytes))
                fail(file, "PLY header claims elements of at least " + std::to_string(needed) +
                               " bytes, but the file holds " + std::to_string(size - std::min(size, headerBytes)) +
                               " after its header");
            return;
        } else {
            bad("unknown keyword '" + keyword + "'");
        }
    }
    fail(file, "PLY header has no end_header line");
}

void checkOff(const std::filesystem::path& file, uint64_t size) {
    std::ifstream in(file, std::ios::binary);
    std::string first;
    in >> first;
    // OpenMesh takes a header that merely contains OFF ("OFFp", with a NUL byte
    // after it) and then spins in its reader, some runs for minutes: only
    // [ST][C][N][4][n]OFF goes on to it. A first word without OFF is OpenMesh's to refuse.
    if (first.find("OFF") == std::string::npos) return;
    const bool known = first.size() >= 3 && first.compare(first.size() - 3, 3, "OFF") == 0 &&
                       first.find_first_not_of("STCN4n") == first.size() - 3;
    if (!known) {
        std::string shown;
        for (char c : first.substr(0, 16)) shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
        fail(file,
             "OFF header '" + shown + "' is not one Lucent reads (expected OFF, COFF, NOFF, STOFF, 4OFF, nOFF ...)");
    }
    std::string word;
    std::vector<uint64_t> counts;
    bool binary = false;
    while (counts.size() < 2 && in >> word) {
        if (word[0] == '#') {
            std::getline(in, word);
            continue;
        }
        if (word == "BINARY") {
            binary = true;
            continue;
        }
        counts.push_back(parseCount(file, word, "OFF"));
    }
    // OpenMesh spins on an OFF file that ends before its counts (just "OFF").
    if (counts.size() < 2) fail(file, "OFF file ends before its vertex and face counts");
    checkCount(file, counts[0], "vertices");
    checkCount(file, counts[1], "faces");
    // ASCII: "0 0 0\n" per vertex, "3 0 1 2\n" per face; binary: 12 and 16 bytes.
    const uint64_t needed = binary ? 12 * counts[0] + 16 * counts[1] : 6 * counts[0] + 8 * counts[1];
    if (needed > size)
        fail(file, "OFF header claims " + std::to_string(counts[0]) + " vertices and " + std::to_string(counts[1]) +
                       " faces, at least " + std::to_string(needed) + " bytes, but the file holds " +
                       std::to_string(size));
}

// Face indices of an OBJ against the vertices declared before them (OBJ allows
// negative indices, relative to the last vertex read).
void checkObj(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    int64_t vertices = 0;
    uint64_t lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (line.size() > 1 && line[0] == 'v' && (line[1] == ' ' || line[1] == '\t')) {
            if (++vertices > int64_t(kMaxMeshElements)) checkCount(file, uint64_t(vertices), "vertices");
            continue;
        }
        if (line.size() < 2 || line[0] != 'f' || (line[1] != ' ' && line[1] != '\t')) continue;
        std::istringstream words(line.substr(2));
        std::string corner;
        while (words >> corner) {
            const std::string index = corner.substr(0, corner.find('/'));
            int64_t i = 0;
            const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), i);
            if (error != std::errc() || end != index.data() + index.size()) continue;  // OpenMesh reports it
            const int64_t resolved = i < 0 ? vertices + i + 1 : i;
            if (resolved < 1 || resolved > vertices)
                fail(file, "line " + std::to_string(lineNumber) + ": face refers to vertex " + index + ", but " +
                               std::to_string(vertices) + " vertices come before it");
        }
    }
}

}  // namespace

void checkMeshFileClaims(const std::filesystem::path& file, const std::string& extension, uint64_t size) {
    if (extension == ".ply")
        checkPly(file, size);
    else if (extension == ".off")
        checkOff(file, size);
    else if (extension == ".obj")
        checkObj(file);
}

}  // namespace lucent
