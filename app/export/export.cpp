// The model writers, streamed: glTF binary, OBJ + MTL, PLY (SVG is svg.cpp), all through one
// buffered, atomic output.
//
// Index of this file:
//   [SECTION] Output, progress, numbers
//   [SECTION] glTF binary
//   [SECTION] OBJ + MTL
//   [SECTION] PLY
//   [SECTION] Formats and the one entry

#include "app/export/export.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

#include "app/export/scene.hpp"
#include "app/export/svg.hpp"
#include "app/mesh/texture_images.hpp"
#include "core/base/atomic_file.hpp"

// [SECTION] Output, progress, numbers
namespace sprout::exporter {
namespace {

// Buffered output that remembers the first failure, streamed into an AtomicFile: a full disk
// or a failed write leaves the old file and no partial one.
class Out {
public:
    explicit Out(const std::string& path) {
        std::string error;
        if (!m_file.open(path, error)) m_error = error;
        m_buffer.reserve(kBuffer);
    }
    bool ok() const { return m_error.empty(); }
    const std::string& error() const { return m_error; }
    std::uint64_t bytes() const { return m_bytes + m_buffer.size(); }

    void write(const void* data, std::size_t n) {
        const char* p = static_cast<const char*>(data);
        if (m_buffer.size() + n > kBuffer) flush();
        if (n > kBuffer) {
            put(p, n);
            return;
        }
        m_buffer.insert(m_buffer.end(), p, p + n);
    }
    void text(std::string_view s) { write(s.data(), s.size()); }
    // Shortest float text that reads back to the same value.
    void number(float v) {
        char tmp[32];
        auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
        write(tmp, std::size_t(r.ptr - tmp));
    }
    void number(std::uint64_t v) {
        char tmp[24];
        auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
        write(tmp, std::size_t(r.ptr - tmp));
    }
    // Writes what is buffered; the file becomes the target's only with commit().
    bool close() {
        flush();
        return ok();
    }
    bool commit() {
        if (!close()) {
            m_file.abort();
            return false;
        }
        std::string error;
        if (!m_file.commit(error)) m_error = error;
        return ok();
    }

private:
    static constexpr std::size_t kBuffer = 1 << 20;
    void flush() {
        put(m_buffer.data(), m_buffer.size());
        m_buffer.clear();
    }
    void put(const char* p, std::size_t n) {
        if (!m_error.empty() || !n) return;
        if (!m_file.write(p, n)) m_error = m_file.error();
        m_bytes += n;
    }
    AtomicFile m_file;
    std::string m_error;
    std::vector<char> m_buffer;
    std::uint64_t m_bytes = 0;
};

// Closes the file; the byte count, or the first write error.
bool finish(Out& out, ExportStats& st, std::string& error) {
    st.bytes = out.bytes();
    if (out.commit()) return true;
    error = out.error();
    return false;
}

// Reports progress by items written, at most a few hundred times.
class Progress {
public:
    Progress(const ExportOptions& o, const std::vector<Primitive>& prims, int passes) : m_o(o) {
        for (const auto& p : prims) m_total += double(p.items.size()) * passes;
    }
    void advance(std::size_t items) {
        m_done += double(items);
        if (!m_o.progress || m_total <= 0) return;
        double f = m_done / m_total;
        if (f - m_last >= 0.005 || f >= 1.0) {
            m_last = f;
            m_o.progress(std::min(f, 1.0));
        }
    }

private:
    const ExportOptions& m_o;
    double m_total = 0, m_done = 0, m_last = -1;
};

std::string hexColour(std::uint32_t rgba) {
    char b[16];
    std::snprintf(b, sizeof b, "%06x", unsigned(rgba >> 8));
    return b;
}

std::array<float, 4> linearColour(std::uint32_t rgba) {
    return {srgbToLinear(std::uint8_t(rgba >> 24)), srgbToLinear(std::uint8_t(rgba >> 16)),
            srgbToLinear(std::uint8_t(rgba >> 8)), float(rgba & 0xffu) / 255.0f};
}

std::string fmt(float v) {
    char tmp[32];
    auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
    return std::string(tmp, r.ptr);
}

std::string jsonString(std::string_view s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') o += '\\';
        if (std::uint8_t(c) < 0x20) continue;
        o += c;
    }
    return o + "\"";
}

const char* kParts[] = {"stems", "leaves", "petals", "spheres", "polygons"};

// How the surfaces of a colour shine (Geometry::shines: the first listed), or null.
const Shine* shineOf(const Geometry& g, std::uint32_t colour) {
    for (const auto& [c, s] : g.shines)
        if (c == colour) return &s;
    return nullptr;
}

// [SECTION] glTF binary
// ---------------------------------------------------------------------------------- glTF
// The images of a scene's textured primitives that can be read (a PNG or JPEG file's bytes, an SGI
// image as a PNG): their bytes, types and names, and by Geometry::textures id the glTF texture
// of each, its place in these (-1: none). The .glb embeds them, the .obj writes them beside it.
struct SceneImages {
    std::vector<std::string> bytes, mimes, names;
    std::vector<int> texture;
};
// A primitive's glTF texture, -1: none.
int textureOf(const SceneImages& images, const Primitive& p) { return p.texture < images.texture.size() ? images.texture[p.texture] : -1; }
SceneImages sceneImages(const ExportScene& scene) {
    SceneImages out;
    const auto& paths = scene.geometry().textures;
    out.texture.assign(paths.size() + 1, -1);
    std::vector<bool> tried(paths.size() + 1, false);
    for (const auto& p : scene.primitives) {
        if (p.texture == 0 || p.texture > paths.size() || tried[p.texture]) continue;
        tried[p.texture] = true;
        std::string mime;
        std::string bytes = mesh::imageFileBytes(paths[p.texture - 1], mime);
        if (bytes.empty()) continue;
        out.texture[p.texture] = int(out.bytes.size());
        out.bytes.push_back(std::move(bytes));
        out.mimes.push_back(mime);
        out.names.push_back(std::filesystem::path(paths[p.texture - 1]).stem().string());
    }
    return out;
}

// The materials, one per colour, sidedness and image (`materialOf` numbers them), as glTF's JSON.
using MaterialKey = std::tuple<std::uint32_t, bool, int>;
std::string glbMaterials(const ExportScene& scene, const SceneImages& images, std::map<MaterialKey, std::size_t>& materialOf) {
    std::string materials;
    for (const auto& p : scene.primitives) {
        auto key = std::make_tuple(p.colour, p.doubleSided, textureOf(images, p));
        if (materialOf.count(key)) continue;
        materialOf[key] = materialOf.size();
        const int texture = textureOf(images, p);
        auto c = linearColour(p.colour);
        // A shining material: smoother as it is shinier, and its emission (glTF's factors).
        const Shine* shine = shineOf(scene.geometry(), p.colour);
        const auto e = linearColour(shine ? shine->emission | 0xFFu : 0xFFu);
        if (!materials.empty()) materials += ",";
        materials += "{\"name\":" + jsonString((p.doubleSided ? "surface_" : "bark_") + hexColour(p.colour) +
                                                 (texture >= 0 ? "_" + images.names[size_t(texture)] : "")) +
                     ",\"pbrMetallicRoughness\":{\"baseColorFactor\":[" + fmt(c[0]) + "," + fmt(c[1]) + "," + fmt(c[2]) + "," +
                     fmt(c[3]) + "]" + (texture >= 0 ? ",\"baseColorTexture\":{\"index\":" + std::to_string(texture) + "}" : "") +
                     ",\"metallicFactor\":0,\"roughnessFactor\":" +
                     fmt(shine ? std::clamp(1.0f - shine->shininess, 0.05f, 1.0f) : 0.8f) + "}" +
                     (shine && shine->emission ? ",\"emissiveFactor\":[" + fmt(e[0]) + "," + fmt(e[1]) + "," + fmt(e[2]) + "]" : "") +
                     (c[3] < 1               ? ",\"alphaMode\":\"BLEND\""
                      : texture >= 0 ? ",\"alphaMode\":\"MASK\",\"alphaCutoff\":0.5"  // an image's clear parts cut away, as drawn
                                     : "") +
                     (p.doubleSided ? ",\"doubleSided\":true" : "") + "}";
    }
    return materials;
}

// The binary chunk's bytes: each primitive's vertices (position, normal), indices and, textured,
// its texture coordinates; then the images at `imageAt`, zeros to `end` between.
void writeGlbBuffer(Out& out, const ExportScene& scene, const SceneImages& images, const std::vector<std::uint64_t>& imageAt, std::uint64_t end,
                    const ExportOptions& o) {
    const auto& prims = scene.primitives;
    Progress progress(o, prims, 2);
    std::vector<float> verts;
    std::vector<std::uint32_t> idx;
    for (const char* part : kParts)
        for (const auto& p : prims) {
            if (p.part != part) continue;
            scene.forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
                verts.resize(chunk.vertices.size() * 6);
                float* w = verts.data();
                for (const auto& v : chunk.vertices) {
                    std::memcpy(w, &v.position, 12);
                    std::memcpy(w + 3, &v.normal, 12);
                    w += 6;
                }
                out.write(verts.data(), verts.size() * 4);
                progress.advance(4096);
            });
            std::uint32_t base = 0;
            scene.forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
                idx.resize(chunk.indices.size());
                for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = base + chunk.indices[i];
                base += std::uint32_t(chunk.vertices.size());
                out.write(idx.data(), idx.size() * 4);
                progress.advance(4096);
            });
            if (textureOf(images, p) >= 0)  // glTF's v runs down the image from its top
                scene.forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
                    verts.resize(chunk.vertices.size() * 2);
                    for (std::size_t i = 0; i < chunk.vertices.size(); ++i) {
                        const TexCoord t = i < chunk.texcoords.size() ? chunk.texcoords[i] : TexCoord{};
                        verts[2 * i] = t.u, verts[2 * i + 1] = 1.0f - t.v;
                    }
                    out.write(verts.data(), verts.size() * 4);
                });
        }
    std::uint64_t at = 0;  // where the primitives' bytes end: the images after them
    for (const auto& p : prims)
        at += std::uint64_t(p.vertices) * 24 + std::uint64_t(p.indices) * 4 + (textureOf(images, p) >= 0 ? std::uint64_t(p.vertices) * 8 : 0);
    const char zeros[4] = {0, 0, 0, 0};
    for (std::size_t k = 0; k < images.bytes.size(); ++k) {
        out.write(zeros, std::size_t(imageAt[k] - at));
        out.text(images.bytes[k]);
        at = imageAt[k] + images.bytes[k].size();
    }
    out.write(zeros, std::size_t(end - at));
}

bool writeGlb(const ExportScene& scene, const std::string& path, const ExportOptions& o, ExportStats& st,
              std::string& error) {
    const auto& prims = scene.primitives;
    // The images textured primitives show, embedded (a PNG or JPEG as it is, an SGI as a PNG),
    // each once: by Geometry::textures id, its glTF texture (-1: none, it could not be read).
    const SceneImages images = sceneImages(scene);
    // Materials: one per colour, sidedness and image.
    std::map<MaterialKey, std::size_t> materialOf;
    const std::string materials = glbMaterials(scene, images, materialOf);
    // Per primitive: an interleaved position+normal view and an index view.
    std::string views, accessors, meshes, nodes, sceneNodes;
    std::uint64_t offset = 0;
    std::size_t view = 0, accessor = 0, mesh = 0;
    for (const char* part : kParts) {
        std::string primsJson;
        for (const auto& p : prims) {
            if (p.part != part) continue;
            const bool textured = textureOf(images, p) >= 0;
            const std::uint64_t vbytes = std::uint64_t(p.vertices) * 24, ibytes = std::uint64_t(p.indices) * 4,
                                ubytes = textured ? std::uint64_t(p.vertices) * 8 : 0;
            if (!views.empty()) views += ",";
            views += "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) + ",\"byteLength\":" + std::to_string(vbytes) +
                     ",\"byteStride\":24,\"target\":34962},";
            views += "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset + vbytes) +
                     ",\"byteLength\":" + std::to_string(ibytes) + ",\"target\":34963}";
            if (textured)  // its texture coordinates, after its indices
                views += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(offset + vbytes + ibytes) +
                         ",\"byteLength\":" + std::to_string(ubytes) + ",\"target\":34962}";
            offset += vbytes + ibytes + ubytes;
            if (!accessors.empty()) accessors += ",";
            accessors += "{\"bufferView\":" + std::to_string(view) + ",\"componentType\":5126,\"count\":" +
                         std::to_string(p.vertices) + ",\"type\":\"VEC3\",\"min\":[" + fmt(p.min.x) + "," + fmt(p.min.y) + "," +
                         fmt(p.min.z) + "],\"max\":[" + fmt(p.max.x) + "," + fmt(p.max.y) + "," + fmt(p.max.z) + "]},";
            accessors += "{\"bufferView\":" + std::to_string(view) + ",\"byteOffset\":12,\"componentType\":5126,\"count\":" +
                         std::to_string(p.vertices) + ",\"type\":\"VEC3\"},";
            accessors += "{\"bufferView\":" + std::to_string(view + 1) + ",\"componentType\":5125,\"count\":" +
                         std::to_string(p.indices) + ",\"type\":\"SCALAR\"}";
            if (textured)
                accessors += ",{\"bufferView\":" + std::to_string(view + 2) + ",\"componentType\":5126,\"count\":" +
                             std::to_string(p.vertices) + ",\"type\":\"VEC2\"}";
            if (!primsJson.empty()) primsJson += ",";
            primsJson += "{\"attributes\":{\"POSITION\":" + std::to_string(accessor) + ",\"NORMAL\":" +
                         std::to_string(accessor + 1) + (textured ? ",\"TEXCOORD_0\":" + std::to_string(accessor + 3) : "") +
                         "},\"indices\":" + std::to_string(accessor + 2) + ",\"material\":" +
                         std::to_string(materialOf[{p.colour, p.doubleSided, textureOf(images, p)}]) + ",\"mode\":4}";
            view += textured ? 3 : 2;
            accessor += textured ? 4 : 3;
        }
        if (primsJson.empty()) continue;
        if (!meshes.empty()) meshes += ",", nodes += ",", sceneNodes += ",";
        meshes += "{\"name\":" + jsonString(part) + ",\"primitives\":[" + primsJson + "]}";
        nodes += "{\"name\":" + jsonString(part) + ",\"mesh\":" + std::to_string(mesh) + "}";
        sceneNodes += std::to_string(mesh);
        ++mesh;
    }
    st.materials = materialOf.size();
    // The images' bytes after the primitives', each at a multiple of 4.
    std::string imagesJson;
    std::vector<std::uint64_t> imageAt;
    for (std::size_t k = 0; k < images.bytes.size(); ++k) {
        offset = (offset + 3) / 4 * 4;
        imageAt.push_back(offset);
        views += (views.empty() ? "" : ",") + std::string("{\"buffer\":0,\"byteOffset\":") + std::to_string(offset) +
                 ",\"byteLength\":" + std::to_string(images.bytes[k].size()) + "}";
        imagesJson += (k ? "," : "") + std::string("{\"name\":") + jsonString(images.names[k]) + ",\"bufferView\":" +
                      std::to_string(view++) + ",\"mimeType\":" + jsonString(images.mimes[k]) + "}";
        offset += images.bytes[k].size();
    }
    offset = (offset + 3) / 4 * 4;
    // Texts (L-Py's @L labels): an empty node each where it stands, named by the text (Blender
    // makes each an empty of that name), its size in pixels in extras; under a node "labels".
    if (const auto& labels = scene.geometry().labels; !labels.empty()) {
        std::string children;
        for (std::size_t k = 0; k < labels.size(); ++k) {
            const Geometry::Label& l = labels[k];
            nodes += (nodes.empty() ? "" : ",") + std::string("{\"name\":") + jsonString(l.text) + ",\"translation\":[" +
                     fmt(l.position.x) + "," + fmt(l.position.y) + "," + fmt(l.position.z) + "],\"extras\":{\"label\":" +
                     jsonString(l.text) + ",\"size\":" + fmt(l.size) + "}}";
            children += (k ? "," : "") + std::to_string(mesh + k);
        }
        nodes += ",{\"name\":\"labels\",\"children\":[" + children + "]}";
        sceneNodes += (sceneNodes.empty() ? "" : ",") + std::to_string(mesh + labels.size());
    }
    std::string json = "{\"asset\":{\"version\":\"2.0\",\"generator\":" + jsonString(o.generator) +
                       "},\"scene\":0,\"scenes\":[{\"name\":\"plant\",\"nodes\":[" + sceneNodes + "]}]";
    if (!nodes.empty()) json += ",\"nodes\":[" + nodes + "]";
    if (mesh) {
        json += ",\"meshes\":[" + meshes + "],\"materials\":[" + materials + "],\"accessors\":[" + accessors +
                "],\"bufferViews\":[" + views + "],\"buffers\":[{\"byteLength\":" + std::to_string(offset) + "}]";
        if (!imagesJson.empty()) {  // PlantGL's and cpfg's images repeat (GL_REPEAT: 10497)
            std::string textures;
            for (std::size_t k = 0; k < images.bytes.size(); ++k) textures += (k ? "," : "") + std::string("{\"sampler\":0,\"source\":") + std::to_string(k) + "}";
            json += ",\"images\":[" + imagesJson + "],\"textures\":[" + textures +
                    "],\"samplers\":[{\"magFilter\":9729,\"minFilter\":9987,\"wrapS\":10497,\"wrapT\":10497}]";
        }
    }
    json += "}";
    while (json.size() % 4) json += ' ';
    const std::uint64_t total = 12 + 8 + json.size() + (offset ? 8 + offset : 0);
    if (total > 0xffffffffull) {
        error = "too big for a .glb file (" + std::to_string(total >> 20) + " MB, the format's limit is 4 GB); try --sides 3";
        return false;
    }

    Out out(path);
    auto u32 = [&](std::uint32_t v) { out.write(&v, 4); };
    u32(0x46546C67);  // "glTF"
    u32(2);
    u32(std::uint32_t(total));
    u32(std::uint32_t(json.size()));
    u32(0x4E4F534A);  // "JSON"
    out.text(json);
    if (offset) {
        u32(std::uint32_t(offset));
        u32(0x004E4942);  // "BIN\0"
        writeGlbBuffer(out, scene, images, imageAt, offset, o);
    }
    return finish(out, st, error);
}

// [SECTION] OBJ + MTL
// ----------------------------------------------------------------------------- OBJ + MTL
bool writeObj(const ExportScene& scene, const std::string& path, const ExportOptions& o, ExportStats& st,
              std::string& error) {
    // The pair is written into two temporaries and committed together at the end, the MTL
    // first: a failure leaves both old files. On standard output there is no MTL beside it.
    const bool toStdout = path == "-";
    std::string mtlPath = toStdout ? std::string() : path.substr(0, path.size() - 4) + ".mtl";
    std::string mtlName = mtlPath.substr(mtlPath.find_last_of('/') + 1);
    std::optional<Out> mtlFile;
    // The images textured primitives show, written beside the pair (an SGI image as a PNG) and
    // named by the MTL's map_Kd; by Geometry::textures id, the file's name ("": none).
    std::vector<std::string> imageName(scene.geometry().textures.size() + 1);
    std::vector<std::unique_ptr<Out>> imageFiles;
    auto nameOf = [&](const Primitive& p) {
        return std::string(p.doubleSided ? "surface_" : "bark_") + hexColour(p.colour) +
               (p.texture < imageName.size() && !imageName[p.texture].empty() ? "_" + imageName[p.texture] : "");
    };
    if (!toStdout) {
        const std::string folder = path.substr(0, path.find_last_of('/') + 1);
        const SceneImages images = sceneImages(scene);
        for (std::size_t id = 1; id < imageName.size(); ++id) {
            const int k = images.texture[id];
            if (k < 0) continue;
            const std::string ext = images.mimes[size_t(k)] == "image/jpeg" ? ".jpg" : ".png";
            std::string name = images.names[size_t(k)] + ext;
            for (int n = 2; std::find(imageName.begin(), imageName.end(), name) != imageName.end(); ++n)  // two images of one name
                name = images.names[size_t(k)] + "_" + std::to_string(n) + ext;
            auto& file = imageFiles.emplace_back(std::make_unique<Out>(folder + name));
            file->text(images.bytes[size_t(k)]);
            if (!file->close()) return error = folder + name + ": " + file->error(), false;
            imageName[id] = name;
        }
        Out& mtl = mtlFile.emplace(mtlPath);
        std::map<std::string, bool> seen;
        mtl.text("# " + o.generator + "\n");
        for (const auto& p : scene.primitives) {
            if (seen[nameOf(p)]) continue;
            seen[nameOf(p)] = true;
            auto c = linearColour(p.colour);
            const Shine* shine = shineOf(scene.geometry(), p.colour);  // its specular colour and exponent, its emission
            std::string light = "\nKs 0.05 0.05 0.05\nNs 10";
            if (shine) {
                const auto ks = linearColour(shine->specular | 0xFFu), ke = linearColour(shine->emission | 0xFFu);
                light = "\nKs " + fmt(ks[0]) + " " + fmt(ks[1]) + " " + fmt(ks[2]) + "\nNs " + fmt(std::max(1.0f, 128 * shine->shininess)) +
                        (shine->emission ? "\nKe " + fmt(ke[0]) + " " + fmt(ke[1]) + " " + fmt(ke[2]) : std::string());
            }
            const std::string image = p.texture < imageName.size() ? imageName[p.texture] : "";
            mtl.text("\nnewmtl " + nameOf(p) + "\nKd " + fmt(c[0]) + " " + fmt(c[1]) + " " + fmt(c[2]) + "\nKa 0 0 0" + light + "\nd " +
                     fmt(c[3]) + "\nillum 2\n" + (image.empty() ? "" : "map_Kd " + image + "\n"));
        }
        st.materials = seen.size();
        if (!mtl.close()) {
            error = mtlPath + ": " + mtl.error();
            return false;
        }
    }
    Out out(path);
    out.text("# " + o.generator + "\n" + (toStdout ? std::string() : "mtllib " + mtlName + "\n"));
    Progress progress(o, scene.primitives, 2);
    std::uint64_t base = 1, vtBase = 1;  // OBJ counts from 1
    for (const char* part : kParts) {
        bool first = true;
        for (const auto& p : scene.primitives) {
            if (p.part != part) continue;
            if (first) out.text(std::string("o ") + part + "\n");
            first = false;
            out.text(std::string("g ") + part + "\nusemtl " + nameOf(p) + "\n");
            const bool textured = p.texture && p.texture < imageName.size() && !imageName[p.texture].empty();
            scene.forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
                for (std::size_t i = 0; i < chunk.vertices.size(); ++i) {
                    const auto& v = chunk.vertices[i];
                    out.text("v ");
                    out.number(v.position.x), out.text(" "), out.number(v.position.y), out.text(" "), out.number(v.position.z);
                    out.text("\nvn ");
                    out.number(v.normal.x), out.text(" "), out.number(v.normal.y), out.text(" "), out.number(v.normal.z);
                    if (textured) {  // OBJ's v runs up the image, as Sprout's
                        const TexCoord t = i < chunk.texcoords.size() ? chunk.texcoords[i] : TexCoord{};
                        out.text("\nvt "), out.number(t.u), out.text(" "), out.number(t.v);
                    }
                    out.text("\n");
                }
                progress.advance(4096);
            });
            std::uint64_t local = base;
            scene.forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
                for (std::size_t i = 0; i < chunk.indices.size(); i += 3) {
                    out.text("f");
                    for (int k = 0; k < 3; ++k) {  // vt counted as v: one each, in the same order
                        std::uint64_t n = local + chunk.indices[i + k];
                        out.text(" "), out.number(n), out.text(textured ? "/" : "//");
                        if (textured) out.number(n - base + vtBase), out.text("/");
                        out.number(n);
                    }
                    out.text("\n");
                }
                local += chunk.vertices.size();
                progress.advance(4096);
            });
            base += p.vertices;
            if (textured) vtBase += p.vertices;
        }
    }
    if (!out.close()) {
        error = out.error();
        return false;
    }
    if (mtlFile && !mtlFile->commit()) {
        error = mtlPath + ": " + mtlFile->error();
        return false;
    }
    for (auto& file : imageFiles)
        if (!file->commit()) {
            error = file->error();
            return false;
        }
    return finish(out, st, error);
}

// [SECTION] PLY
// ---------------------------------------------------------------------------------- PLY
bool writePly(const ExportScene& scene, const std::string& path, const ExportOptions& o, ExportStats& st,
              std::string& error) {
    Out out(path);
    out.text("ply\nformat binary_little_endian 1.0\ncomment " + o.generator + "\nelement vertex " + std::to_string(st.vertices) +
             "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
             "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\nelement face " +
             std::to_string(st.triangles) + "\nproperty list uchar uint vertex_indices\nend_header\n");
    Progress progress(o, scene.primitives, 2);
    std::vector<char> buf;
    for (const auto& p : scene.primitives)
        scene.forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
            buf.resize(chunk.vertices.size() * 28);
            char* w = buf.data();
            for (const auto& v : chunk.vertices) {
                std::memcpy(w, &v.position, 12);
                std::memcpy(w + 12, &v.normal, 12);
                const std::uint8_t rgba[4] = {std::uint8_t(v.colour >> 24), std::uint8_t(v.colour >> 16),
                                              std::uint8_t(v.colour >> 8), std::uint8_t(v.colour)};
                std::memcpy(w + 24, rgba, 4);
                w += 28;
            }
            out.write(buf.data(), buf.size());
            progress.advance(4096);
        });
    std::uint32_t base = 0;
    for (const auto& p : scene.primitives)
        scene.forEachChunk(p, [&](const mesh::BakedMesh& chunk) {
            buf.resize(chunk.indices.size() / 3 * 13);
            char* w = buf.data();
            for (std::size_t i = 0; i < chunk.indices.size(); i += 3) {
                *w++ = 3;
                for (int k = 0; k < 3; ++k) {
                    std::uint32_t n = base + chunk.indices[i + k];
                    std::memcpy(w, &n, 4);
                    w += 4;
                }
            }
            base += std::uint32_t(chunk.vertices.size());
            out.write(buf.data(), buf.size());
            progress.advance(4096);
        });
    return finish(out, st, error);
}

}  // namespace

// [SECTION] Formats and the one entry
std::optional<Format> formatFromPath(const std::string& path) {
    auto dot = path.find_last_of('.');
    if (dot == std::string::npos) return std::nullopt;
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == "glb") return Format::Glb;
    if (ext == "obj") return Format::Obj;
    if (ext == "ply") return Format::Ply;
    if (ext == "svg") return Format::Svg;
    return std::nullopt;
}

bool exportGeometry(const Geometry& g, const std::string& path, Format format, const ExportOptions& o, ExportStats& st,
                    std::string& error) {
    st = {};
    if (format == Format::Svg) return writeSvg(g, path, o, st, error);
    ExportScene scene(g, o.sides);
    st.stems = scene.stems();
    for (const auto& p : scene.primitives) {  // every mesh format writes all of them
        st.vertices += p.vertices;
        st.triangles += p.indices / 3;
        ++st.primitives;
    }
    switch (format) {
        case Format::Glb: return writeGlb(scene, path, o, st, error);
        case Format::Obj: return writeObj(scene, path, o, st, error);
        case Format::Ply: return writePly(scene, path, o, st, error);
        case Format::Svg: break;
    }
    return false;
}

}  // namespace sprout::exporter
