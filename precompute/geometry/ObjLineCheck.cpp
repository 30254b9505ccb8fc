/// @file ObjLineCheck.cpp

#include "precompute/geometry/ObjLineCheck.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/PrintableText.h"

namespace modeflow {
namespace {

/// The space- or tab-separated words of a line.
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t pos = 0;
    while (true) {
        pos = line.find_first_not_of(" \t", pos);
        if (pos == std::string_view::npos) return out;
        const std::size_t end = std::min(line.find_first_of(" \t", pos), line.size());
        out.push_back(line.substr(pos, end - pos));
        pos = end;
    }
}

/// `word` read whole as a number (a leading '+' allowed, as tinyobjloader allows it).
template <typename T>
bool readWhole(std::string_view word, T& value) {
    if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    return ec == std::errc{} && end == word.data() + word.size();
}

class LineChecker {
public:
    explicit LineChecker(const std::filesystem::path& file) : mName(file.string()) {}

    void check(std::string_view line) {
        ++mLine;
        const std::vector<std::string_view> w = words(line);
        if (w.empty()) return;
        if (w[0] == "v") checkVertex(w);
        if (w[0] == "f") checkFace(w);
    }

    /// Positive indices may point forward; they are checked against the final count.
    void finish() const {
        if (mHighest > mVertices)
            fail(mHighestLine, "a face refers to vertex " + std::to_string(mHighest) +
                                   ", but the file has " + std::to_string(mVertices) + " vertices");
    }

private:
    [[noreturn]] void fail(std::size_t line, const std::string& what) const {
        throw Error("mesh file " + mName + ", line " + std::to_string(line) + ": " + what);
    }

    void checkVertex(const std::vector<std::string_view>& w) {
        ++mVertices;
        const std::string vertex = "vertex " + std::to_string(mVertices);
        if (w.size() < 4) {
            fail(mLine, vertex + " has " + std::to_string(w.size() - 1) +
                            " coordinates, expected 3 (x y z)");
        }
        for (std::size_t i = 1; i <= 3; ++i) {
            double x = 0.0;
            if (!readWhole(w[i], x))
                fail(mLine, vertex + " coordinate \"" + printableText(w[i]) + "\" is not a number");
            if (!std::isfinite(x))
                fail(mLine, vertex + " coordinate " + printableText(w[i]) + " is not finite");
            // tinyobjloader stores floats: beyond their range the coordinate becomes infinite.
            if (std::abs(x) > std::numeric_limits<float>::max())
                fail(mLine, vertex + " coordinate " + printableText(w[i]) +
                                " is beyond the float range (about 3.4e38)");
        }
    }

    void checkFace(const std::vector<std::string_view>& w) {
        for (std::size_t i = 1; i < w.size(); ++i) {
            const std::string_view index = w[i].substr(0, w[i].find('/'));
            std::int64_t v = 0;
            if (!readWhole(index, v)) {
                fail(mLine, "a face refers to vertex \"" + printableText(w[i]) +
                                "\", which is not a vertex number");
            }
            if (v == 0) fail(mLine, "a face refers to vertex 0 (vertices are numbered from 1)");
            if (v < 0 && -v > mVertices) {
                fail(mLine, "a face refers to vertex " + std::to_string(v) +
                                " (relative), but only " + std::to_string(mVertices) +
                                " vertices precede it");
            }
            if (v > mHighest) {
                mHighest = v;
                mHighestLine = mLine;
            }
        }
    }

    std::string mName;
    std::size_t mLine = 0;
    std::int64_t mVertices = 0;
    std::int64_t mHighest = 0;  ///< the highest positive vertex index of any face
    std::size_t mHighestLine = 0;
};

}  // namespace

void checkObjLines(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error("mesh file " + file.string() + " cannot be opened");
    LineChecker checker(file);
    // Lines end at "\n", "\r\n" or a lone "\r", as tinyobjloader's safeGetline counts them.
    std::string chunk;
    while (std::getline(in, chunk)) {
        std::string_view rest = chunk;
        if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
        for (std::size_t cr; (cr = rest.find('\r')) != std::string_view::npos;) {
            checker.check(rest.substr(0, cr));
            rest.remove_prefix(cr + 1);
        }
        checker.check(rest);
    }
    if (in.bad()) throw Error("mesh file " + file.string() + " could not be read");
    checker.finish();
}

}  // namespace modeflow
