#include "app/render/shader.hpp"

#include <vector>

#include "core/base/embedded_file.hpp"
#include "app/render/gl.hpp"

namespace sprout {
std::span<const EmbeddedFile> embeddedShaders();  // generated
}

namespace sprout::render {
namespace {

// The info log of a shader or a program (glGetShaderiv + glGetShaderInfoLog, or the
// program's pair).
template <class GetIv, class GetLog>
std::string infoLog(GLuint object, GetIv getiv, GetLog getLog) {
    GLint n = 0;
    getiv(object, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(size_t(std::max(n, 1)));
    getLog(object, n, nullptr, log.data());
    return log.data();
}

std::string_view source(std::string_view stem) {
    for (const auto& f : embeddedShaders())
        if (f.stem == stem) return f.data;
    return {};
}

// Resolves `#include "name"` lines (GLSL 3.30 has no includes) from the embedded files.
std::string expand(std::string_view src) {
    std::string out;
    size_t pos = 0;
    while (pos < src.size()) {
        size_t end = src.find('\n', pos);
        if (end == std::string_view::npos) end = src.size();
        std::string_view line = src.substr(pos, end - pos);
        if (line.starts_with("#include \"")) {
            std::string_view name = line.substr(10);
            name = name.substr(0, name.find('"'));
            out += source(name);
        } else {
            out += line;
        }
        out += '\n';
        pos = end + 1;
    }
    return out;
}

GLuint compile(GLenum type, std::string_view stem, std::string& error) {
    std::string_view raw = source(stem);
    if (raw.empty()) {
        error = "missing shader " + std::string(stem);
        return 0;
    }
    std::string src = expand(raw);
    GLuint s = glCreateShader(type);
    const char* text = src.data();
    GLint len = GLint(src.size());
    glShaderSource(s, 1, &text, &len);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        error = std::string(stem) + ": " + infoLog(s, glGetShaderiv, glGetShaderInfoLog);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

}  // namespace

unsigned buildProgram(std::string_view vertex, std::string_view fragment, std::string& error) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertex, error);
    if (!vs) return 0;
    GLuint fs = compile(GL_FRAGMENT_SHADER, fragment, error);
    if (!fs) {
        glDeleteShader(vs);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        error = std::string(vertex) + "+" + std::string(fragment) + ": " + infoLog(p, glGetProgramiv, glGetProgramInfoLog);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

}  // namespace sprout::render
