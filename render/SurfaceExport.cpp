#include "SurfaceExport.h"

#include "CLocaleNumber.h"
#include "OutputFile.h"

#include <QtEndian>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>
#include <tiny_gltf.h>

namespace pf {

namespace {

// ' ' and `value` in the C locale (cLocaleNumber).
void appendNumber(QByteArray& out, double value, std::chars_format format, int precision) {
    out += ' ';
    out += cLocaleNumber(value, format, precision);
}

QByteArray objBytes(const SurfaceMesh& mesh, bool withNormals) {
    const bool withUvs = mesh.uvs.size() == mesh.positions.size();
    QByteArray out;
    out.reserve(static_cast<qsizetype>(mesh.positions.size() * 110 + mesh.triangles.size() * 50));
    out += "# PaperFold sheet surface (Kang & Cho 4.3 subdivision), metres, y up\n";
    if (withUvs) out += "# vt: the material coordinates over the sheet, 0..1\n";
    constexpr auto general = std::chars_format::general, fixed = std::chars_format::fixed;
    for (const Vec3& p : mesh.positions) {
        out += 'v';
        for (int k = 0; k < 3; ++k) appendNumber(out, p[k], general, 9);
        out += '\n';
    }
    if (withUvs)
        for (const Vec2& uv : mesh.uvs) {
            out += "vt";
            appendNumber(out, uv.x(), general, 9);
            appendNumber(out, 1.0 - uv.y(), general, 9);
            out += '\n';
        }
    if (withNormals)
        for (const Vec3& n : mesh.normals) {
            out += "vn";
            for (int k = 0; k < 3; ++k) appendNumber(out, n[k], fixed, 6);
            out += '\n';
        }
    char line[64];
    // One index serves position, uv and normal alike: "i", "i/i", "i//i" or "i/i/i".
    const char* corner =
        withUvs ? (withNormals ? " %u/%u/%u" : " %u/%u") : (withNormals ? " %u//%u" : " %u");
    for (const auto& t : mesh.triangles) {
        out += 'f';
        for (std::uint32_t v : t) {
            std::snprintf(line, sizeof line, corner, v + 1, v + 1, v + 1);
            out += line;
        }
        out += '\n';
    }
    return out;
}

template <class T> void appendLE(QByteArray& out, T v) {
    const T le = qToLittleEndian(v);
    out.append(reinterpret_cast<const char*>(&le), sizeof le);
}

QByteArray plyBytes(const SurfaceMesh& mesh, bool withNormals) {
    const bool withUvs = mesh.uvs.size() == mesh.positions.size();
    QByteArray out;
    out += "ply\nformat binary_little_endian 1.0\ncomment PaperFold sheet surface, metres, y up\n";
    out += "element vertex " + QByteArray::number(static_cast<qulonglong>(mesh.positions.size())) +
           "\n";
    out += "property float x\nproperty float y\nproperty float z\n";
    if (withNormals) out += "property float nx\nproperty float ny\nproperty float nz\n";
    if (withUvs) out += "property float s\nproperty float t\n";
    out +=
        "element face " + QByteArray::number(static_cast<qulonglong>(mesh.triangles.size())) + "\n";
    out += "property list uchar uint vertex_indices\nend_header\n";
    auto putFloat = [&out](double d) {
        quint32 bits;
        const float f = static_cast<float>(d);
        std::memcpy(&bits, &f, 4);
        appendLE(out, bits);
    };
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) putFloat(mesh.positions[i][k]);
        if (withNormals)
            for (int k = 0; k < 3; ++k) putFloat(mesh.normals[i][k]);
        if (withUvs) {
            putFloat(mesh.uvs[i].x());
            putFloat(1.0 - mesh.uvs[i].y());
        }
    }
    for (const auto& t : mesh.triangles) {
        out.append(char(3));
        for (std::uint32_t v : t) appendLE(out, static_cast<quint32>(v));
    }
    return out;
}

// The sRGB transfer function's inverse (IEC 61966-2-1).
double srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

int addView(tinygltf::Model& model, std::vector<unsigned char>& data, const void* bytes,
            std::size_t size, int target) {
    while (data.size() % 4) data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), p, p + size);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size()) - 1;
}

QByteArray glbBytes(const SurfaceMesh& mesh, bool withNormals, const SurfaceLook& look,
                    QString* error) {
    const bool withUvs = mesh.uvs.size() == mesh.positions.size();
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "PaperFold";
    model.buffers.emplace_back();
    std::vector<unsigned char>& data = model.buffers[0].data;

    std::vector<float> positions, normals, uvs;
    std::vector<std::uint32_t> indices;
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -lo[0]);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const float f = static_cast<float>(mesh.positions[i][k]);
            positions.push_back(f);
            lo[k] = std::min<double>(lo[k], f);
            hi[k] = std::max<double>(hi[k], f);
            normals.push_back(static_cast<float>(mesh.normals[i][k]));
        }
    if (withUvs)
        for (const Vec2& uv : mesh.uvs) uvs.insert(uvs.end(), {float(uv.x()), float(uv.y())});
    for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());

    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    const int pv =
        addView(model, data, positions.data(), positions.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER);
    prim.attributes["POSITION"] = addAccessor(model, pv, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                              TINYGLTF_TYPE_VEC3, mesh.positions.size());
    model.accessors.back().minValues = lo; // required for POSITION by the glTF spec
    model.accessors.back().maxValues = hi;
    if (withNormals) {
        const int nv =
            addView(model, data, normals.data(), normals.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER);
        prim.attributes["NORMAL"] = addAccessor(model, nv, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                TINYGLTF_TYPE_VEC3, mesh.positions.size());
    }
    if (withUvs) {
        const int tv =
            addView(model, data, uvs.data(), uvs.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER);
        prim.attributes["TEXCOORD_0"] = addAccessor(model, tv, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                                    TINYGLTF_TYPE_VEC2, mesh.positions.size());
    }
    const int iv = addView(model, data, indices.data(), indices.size() * 4,
                           TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    prim.indices = addAccessor(model, iv, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                               TINYGLTF_TYPE_SCALAR, indices.size());

    tinygltf::Material paper;
    paper.name = "paper";
    paper.doubleSided = true; // a sheet is seen from both sides
    // glTF's factor is linear light; the look's colour is sRGB, as the view shows it.
    paper.pbrMetallicRoughness.baseColorFactor = {
        srgbToLinear(look.color[0]), srgbToLinear(look.color[1]), srgbToLinear(look.color[2]), 1.0};
    paper.pbrMetallicRoughness.metallicFactor = 0.0;
    paper.pbrMetallicRoughness.roughnessFactor = 0.9;
    if (withUvs && !look.texturePng.isEmpty()) {
        // The picture travels inside the file: a bufferView with a MIME type.
        tinygltf::Image image;
        image.name = "paper";
        image.mimeType = "image/png";
        image.bufferView = addView(model, data, look.texturePng.constData(),
                                   static_cast<std::size_t>(look.texturePng.size()), 0);
        model.images.push_back(image);
        tinygltf::Sampler sampler;
        sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
        sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        model.samplers.push_back(sampler);
        tinygltf::Texture texture;
        texture.source = 0;
        texture.sampler = 0;
        model.textures.push_back(texture);
        paper.pbrMetallicRoughness.baseColorTexture.index = 0;
        paper.pbrMetallicRoughness.baseColorTexture.texCoord = 0;
    }
    model.materials.push_back(paper);
    prim.material = 0;

    tinygltf::Mesh m;
    m.name = "sheet";
    m.primitives.push_back(prim);
    model.meshes.push_back(m);
    tinygltf::Node node;
    node.mesh = 0;
    node.name = "sheet";
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    std::ostringstream stream;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, stream, false, true)) {
        if (error) *error = QStringLiteral("the glTF writer failed");
        return {};
    }
    const std::string s = stream.str();
    return QByteArray(s.data(), static_cast<qsizetype>(s.size()));
}

} // namespace

bool meshFormatForPath(const QString& path, MeshFormat* format) {
    const QString lower = path.toLower();
    if (lower.endsWith(QLatin1String(".obj")))
        *format = MeshFormat::Obj;
    else if (lower.endsWith(QLatin1String(".ply")))
        *format = MeshFormat::Ply;
    else if (lower.endsWith(QLatin1String(".glb")))
        *format = MeshFormat::Glb;
    else
        return false;
    return true;
}

bool writeSurface(const SurfaceMesh& mesh, const QString& path, MeshFormat format, bool withNormals,
                  const SurfaceLook& look, QString* error, const QStringList& inputs) {
    QByteArray bytes;
    switch (format) {
    case MeshFormat::Obj:
        bytes = objBytes(mesh, withNormals);
        break;
    case MeshFormat::Ply:
        bytes = plyBytes(mesh, withNormals);
        break;
    case MeshFormat::Glb:
        bytes = glbBytes(mesh, withNormals, look, error);
        if (bytes.isEmpty()) return false;
        break;
    }
    return writeOutputFile(path, bytes, error, inputs);
}

} // namespace pf
