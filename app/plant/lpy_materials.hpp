#pragma once
// An L-Py model's materials as its INITIALISATION part sets them (issue 52): the colour map
// the panel's material editor changes, read and written in place like its curves
// (lpy_objects.hpp), so the text stays the one source of truth and L-Py reads it back. Two
// forms are read, as L-Py Studio writes them:
//     Color_0 = pgl.Material("Color_0" , ambient = (30,60,10) , diffuse = 3 , )
//     context.turtle.setMaterial(0,Color_0)
// (only the fields that are not PlantGL's defaults), and the older
//     context.turtle.setMaterial(0,Material('Red',Color3(39,0,0),4.6,Color3(40,40,40),Color3(0,0,0),1,0))
// An ImageTexture (alone or in a Texture2D) is listed with its image, which setLpyTextureFile
// changes.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sprout {

struct LpyMaterial {
    // PlantGL's Material: colours 0..255, diffuse a factor of the ambient colour (PlantGL's
    // diffuseColor = ambient * diffuse), shininess and transparency 0..1.
    enum Field { Ambient, Diffuse, Specular, Emission, Shininess, Transparency };
    int index = 0;
    std::string name;
    std::array<int, 3> ambient{80, 80, 80}, specular{0, 0, 0}, emission{0, 0, 0};  // PlantGL's defaults
    double diffuse = 2, shininess = 0.2, transparency = 0;
    std::string texture;  // an ImageTexture's image ("": a Material)
    std::array<size_t, 2> textureSpan{};  // where the image's file name (its quoted literal) is; begin == end: none
    int line = 0;         // of its setMaterial, 1-based
    // Where each field's value is in the text (begin == end: not written, PlantGL's default),
    // and where a field not written goes (before the call's ')').
    std::array<std::array<size_t, 2>, 6> spans{};
    size_t insertAt = 0;
    bool keywords = true;  // fields written `name = value` (Studio's form), else by position
};

std::vector<LpyMaterial> lpyMaterials(std::string_view text);
// The text with material m's `field` set from `value` (a colour's three numbers, else the
// first), as Studio writes it; nothing else changes.
std::string setLpyMaterial(std::string_view text, const LpyMaterial& m, LpyMaterial::Field field, const LpyMaterial& value);
// The materials between `from` and `to` (both set, not textures) made the mix of the two, as
// L-Py's colour map interpolates a range: each field linearly (colours rounded), the ones the
// text sets written in place, the others added after the last setMaterial in Studio's form
// (`Color_K = pgl.Material("Color_K" , ambient = (...) , ... , )`). "" and `error` otherwise.
std::string interpolateLpyMaterials(std::string_view text, int from, int to, std::string& error);
// The text with texture material m's image file named `file` (a Python string literal in its
// place); "" and `error` for a material that is no texture, or a name no literal can hold.
std::string setLpyTextureFile(std::string_view text, const LpyMaterial& m, std::string_view file, std::string& error);
const char* lpyMaterialFieldName(LpyMaterial::Field f);  // ambient, diffuse, ...
std::optional<LpyMaterial::Field> lpyMaterialFieldNamed(std::string_view name);
// The diffuse factor PlantGL's Material keeps: no more than keeps every channel of ambient x
// diffuse in 255 (its constructor clamps it so).
double lpyMostDiffuse(const std::array<int, 3>& ambient);
double lpyEffectiveDiffuse(const LpyMaterial& m);
// PlantGL's diffuse colour (floor of ambient x its diffuse), as the turtle draws the material.
std::array<int, 3> lpyDiffuseColour(const LpyMaterial& m);

}  // namespace sprout
