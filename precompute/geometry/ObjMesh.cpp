/// @file ObjMesh.cpp

#include "precompute/geometry/ObjMesh.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <string>
#include <system_error>

#include "engine/core/Error.h"
#include "engine/core/FileKind.h"
#include "precompute/geometry/ObjLineCheck.h"

namespace modeflow {
namespace {

namespace fs = std::filesystem;

std::string trimmed(std::string s) {
    while (!s.empty() &&
           (s.back() == '\n' || s.back() == '\r' || s.back() == ' ' || s.back() == '.'))
        s.pop_back();
    return s;
}

}  // namespace

TriangleMesh readObjMesh(const fs::path& file) {
    const std::string name = file.string();
    if (auto why = whyNotARegularFile(file)) {
        std::error_code ec;
        throw Error("mesh file " + name + " " + *why +
                    (fs::exists(file, ec) ? ", not a regular file" : ""));
    }
    // Names bad vertices and faces with their line first; the checks below guard what
    // tinyobjloader returns.
    checkObjLines(file);

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(name, config)) {
        const std::string why = trimmed(reader.Error());
        throw Error("mesh file " + name + " is not a valid OBJ file" +
                    (why.empty() ? std::string() : ": " + why));
    }

    TriangleMesh mesh;
    const auto& coords = reader.GetAttrib().vertices;
    const std::size_t vertexCount = coords.size() / 3;
    mesh.vertices.reserve(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) {
        const Vec3 p{coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]};
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw Error("mesh file " + name + ": vertex " + std::to_string(i + 1) +
                        " has a non-finite coordinate");
        mesh.vertices.push_back(p);
    }

    std::size_t faceCount = 0;
    for (const auto& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            std::vector<int> face;
            for (unsigned c = 0; c < corners; ++c) {
                const int v = shape.mesh.indices[offset + c].vertex_index;
                if (v < 0 || static_cast<std::size_t>(v) >= vertexCount)
                    throw Error("mesh file " + name + ": a face refers to vertex " +
                                std::to_string(v + 1) + " but the file has " +
                                std::to_string(vertexCount) + " vertices");
                face.push_back(v);
            }
            offset += corners;
            ++faceCount;
            // Fans for anything tinyobjloader left as a polygon.
            for (std::size_t c = 1; c + 1 < face.size(); ++c)
                mesh.triangles.push_back({face[0], face[c], face[c + 1]});
        }
    }
    if (faceCount == 0) {
        throw Error("mesh file " + name + " has no faces" +
                    (vertexCount == 0 ? std::string(" and no vertices: not an OBJ mesh")
                                      : " (only " + std::to_string(vertexCount) + " vertices)") +
                    "; a closed triangle surface is needed");
    }
    return mesh;
}

}  // namespace modeflow
