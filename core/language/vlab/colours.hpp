#pragma once
// A VLab object's colours: material sets (`.mat`, as VLab's medit writes them and cpfg reads
// them, irisGL.c load_in_materials) and colour maps (`.map`, as palette writes them, irisGL.c
// load_in_colormaps), and how cpfg's -M[n] / -m[n] numbering makes one table of colour
// indices: set n holds indices 256 n .. 256 n + 255, and `;(k)` picks index 256 c + k, c being
// the reference set (-c, default 1).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sprout::vlab {

// One material: 0..1 RGB colours, shininess 0..255 (OpenGL's exponent, 0..128 in practice),
// and transparency 0 (opaque) .. 1.
struct Material {
    std::array<float, 3> ambient{0, 0, 0}, diffuse{1, 1, 1}, emission{0, 0, 0}, specular{0, 0, 0};
    float shininess = 0;
    float transparency = 0;
};

// A material set: up to 256 materials by index; an index the file does not give is absent.
struct MaterialSet {
    std::array<std::optional<Material>, 256> materials;
    int count = 0;  // how many the file gave
};

// A colour map: 256 colours, 0xRRGGBB.
struct ColourMap {
    std::array<std::uint32_t, 256> colours{};
};

// Reads the bytes of a .mat file: records of 15 bytes (the index, then transparency, ambient
// RGB, diffuse RGB, emission RGB, specular RGB, shininess). A file whose length is not a
// whole number of records is refused: `error` names the byte offset and what was expected.
std::optional<MaterialSet> readMaterials(std::string_view bytes, std::string& error);

// Reads the bytes of a .map file: 256 RGB triples (768 bytes). A shorter file is refused with
// the byte offset where it ends; a longer one (palette writes some with more) uses its first 768.
std::optional<ColourMap> readColourMap(std::string_view bytes, std::string& error);

// The bytes medit writes (medit/mwviewer.cpp, MWViewer::write): a 15-byte record for each
// material the set has, by index, each value times 255 truncated to a byte (shininess
// truncated), so a file read and written again is the same byte for byte.
std::string writeMaterials(const MaterialSet& set);
// The bytes palette writes (palette/glcolourmap.cpp, SAVE): 256 RGB triples, 768 bytes.
std::string writeColourMap(const ColourMap& map);

// The set number an option names: `-M` and `-m` are set 1, `-M2` set 2 (cpfg's control.c);
// nullopt when the number is out of 0..11 (cpfg ignores it).
std::optional<int> colourSetNumber(std::string_view option);

// The RGBA colour (0xRRGGBBAA) a material gives Sprout's palette: its diffuse colour plus its
// emission (the renderer lights it), alpha from its transparency.
std::uint32_t materialColour(const Material& m);

}  // namespace sprout::vlab
