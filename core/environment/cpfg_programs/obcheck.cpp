// obcheck (the CelticKnot object's own program, obcheck.c): line obstacles a path must not
// cross. ?E(0) marks where a segment starts (the turtle's x and y); ?E(v), v != 0, ends it there
// and is answered 1 when the segment from the last start meets an obstacle (obcheck's test, with
// its tolerance 0.1), else 0, and then the segment's end is the next one's start. Answered at
// once, one ?E after another, the start kept from step to step. Its file: `line width: W`,
// `coordinates:`, then four numbers an obstacle (x1 y1 x2 y2), 100 at most.
#include <cctype>
#include <cstdlib>

#include "core/environment/cpfg_programs/spec_file.hpp"

namespace sprout::cpfgprog {
namespace {

struct Segment {
    float xa = 0, ya = 0, xb = 0, yb = 0;
};

struct Obcheck : EnvironmentProgram {
    std::vector<Segment> obstacles;
    std::unique_ptr<ProgramRun> start() const override;
};

float side(float x, float y, const Segment& l) { return (x - l.xa) * (l.yb - l.ya) - (y - l.ya) * (l.xb - l.xa); }

bool intersect(const Segment& a, const Segment& b) {
    const float epsilon = 0.1f;
    const float v11 = side(a.xa, a.ya, b), v12 = side(a.xb, a.yb, b), v21 = side(b.xa, b.ya, a), v22 = side(b.xb, b.yb, a);
    return v11 * v12 <= epsilon && v21 * v22 <= epsilon;
}

class ObcheckRun : public ProgramRun {
public:
    explicit ObcheckRun(const Obcheck& p) : m_p(p) {}
    void pass(std::vector<ProgramQuery>& queries) override {
        for (ProgramQuery& q : queries) {
            if (q.params.empty()) continue;
            if (q.params[0] == 0) {
                m_line.xa = q.position.v[0];
                m_line.ya = q.position.v[1];
                continue;  // answered with nothing set
            }
            m_line.xb = q.position.v[0];
            m_line.yb = q.position.v[1];
            bool hit = false;
            for (const Segment& o : m_p.obstacles)
                if (intersect(m_line, o)) {
                    hit = true;
                    break;
                }
            q.answer.assign(q.params.begin(), q.params.end());
            q.set.assign(q.params.size(), false);
            q.answer[0] = hit ? 1.0f : 0.0f;
            q.set[0] = true;
            if (!hit) m_line.xa = m_line.xb, m_line.ya = m_line.yb;
        }
    }

private:
    const Obcheck& m_p;
    Segment m_line;  // the turtle's last start and end
};

std::unique_ptr<ProgramRun> Obcheck::start() const { return std::make_unique<ObcheckRun>(*this); }

}  // namespace

std::shared_ptr<EnvironmentProgram> makeObcheck(const std::string&, const std::string& text, const Sink& sink) {
    auto p = std::make_shared<Obcheck>();
    // fscanf "line width: %f\n", then "coordinates:\n", then four numbers at a time.
    size_t at = 0;
    int line = 1;
    auto skipSpace = [&] {
        while (at < text.size() && std::isspace((unsigned char)text[at])) line += text[at++] == '\n';
    };
    auto literal = [&](const char* word) {
        skipSpace();
        const std::string w(word);
        if (text.compare(at, w.size(), w) != 0) return false;
        at += w.size();
        return true;
    };
    auto number = [&](float& v) {
        skipSpace();
        const char* s = text.c_str() + at;
        char* end = nullptr;
        v = std::strtof(s, &end);
        if (end == s) return false;
        at += size_t(end - s);
        return true;
    };
    float width = 0;
    if (literal("line width:")) number(width);
    literal("coordinates:");
    for (;;) {
        Segment s;
        skipSpace();
        const int startLine = line;
        if (at >= text.size()) break;
        float* ends[4] = {&s.xa, &s.ya, &s.xb, &s.yb};
        int got = 0;
        while (got < 4 && number(*ends[got])) ++got;
        if (got < 4) {
            sink.warning(startLine, "expected an obstacle's four numbers (x1 y1 x2 y2)" + std::string(got ? "" : " or the file's end") +
                                        "; obcheck stops reading here, with " + std::to_string(p->obstacles.size()) + " obstacles");
            break;
        }
        if (p->obstacles.size() == 100) {
            sink.warning(startLine, "obcheck holds 100 obstacles at most; the rest are left out");
            break;
        }
        p->obstacles.push_back(s);
    }
    return p;
}

}  // namespace sprout::cpfgprog
