// honda81 (VLab's ENVIRO/honda81): branches that stop where another's end is near (Honda 1981,
// the Sierpinski object). ?E(vigor[, group]) is answered 1 (may grow) or 0 (another ?E of the
// same group with a vigor at least as high is within `radius`), all of a pass at once.
// Specification: `verbose: on|off`, `radius: R`, `3d case: on|off` (off: x and z are compared).
#include <cmath>

#include "core/environment/cpfg_programs/spec_file.hpp"

namespace sprout::cpfgprog {
namespace {

struct Honda81 : EnvironmentProgram {
    float radius2 = 0;  // squared, in float as honda81 keeps it
    bool is3d = false;
    std::unique_ptr<ProgramRun> start() const override;
};

class Honda81Run : public ProgramRun {
public:
    explicit Honda81Run(const Honda81& p) : m_p(p) {}
    void pass(std::vector<ProgramQuery>& queries) override {
        struct Item {
            float pos[3];
            float vigor;
            int index;
            ProgramQuery* q;
        };
        std::vector<Item> items;
        for (ProgramQuery& q : queries) {
            // StoreQuery: the position's three numbers and a parameter are needed.
            if (q.position.count < 3 || q.params.empty()) continue;
            Item it{};
            it.pos[0] = q.position.v[0];
            if (m_p.is3d) {
                it.pos[1] = q.position.v[1];
                it.pos[2] = q.position.v[2];
            } else {
                it.pos[1] = q.position.v[2];
            }
            it.vigor = q.params[0];
            it.index = q.params.size() > 1 ? toInt(q.params[1]) : 0;  // huge or NaN: a bound, not UB
            it.q = &q;
            items.push_back(it);
        }
        for (size_t i = 0; i < items.size(); ++i) {
            float value = 1;
            for (size_t j = 0; j < items.size(); ++j) {
                if (i == j || items[i].index != items[j].index || !(items[i].vigor <= items[j].vigor)) continue;
                float v0 = items[i].pos[0] - items[j].pos[0], v1 = items[i].pos[1] - items[j].pos[1];
                if (m_p.is3d) {
                    float v2 = items[i].pos[2] - items[j].pos[2];
                    if (v0 * v0 + v1 * v1 + v2 * v2 <= m_p.radius2) value = 0;
                } else if (v0 * v0 + v1 * v1 <= m_p.radius2) {
                    value = 0;
                }
            }
            items[i].q->reply({value});
        }
    }

private:
    const Honda81& m_p;
};

std::unique_ptr<ProgramRun> Honda81::start() const { return std::make_unique<Honda81Run>(*this); }

}  // namespace

std::shared_ptr<EnvironmentProgram> makeHonda81(const std::string&, const std::string& text, const Sink& sink) {
    auto p = std::make_shared<Honda81>();
    const std::vector<std::string> keywords{"verbose", "radius", "3d case"};
    for (const SpecLine& line : specLines(text)) {
        const std::vector<Token> t = tokensOf(line, "x,; \t:\n");
        if (line.keyword == "verbose") {
        } else if (line.keyword == "radius") {
            if (t.empty()) {
                sink.warning(line.number, "'radius': expected a number (the distance within which a branch stops another)");
                continue;
            }
            p->radius2 = float(numberOf(t[0], line, sink, "a number"));
            p->radius2 *= p->radius2;
        } else if (line.keyword == "3d case") {
            if (!t.empty()) p->is3d = t[0].text == "on";
        } else {
            unknownKeyword(line, keywords, "honda81", sink);
        }
    }
    return p;
}

}  // namespace sprout::cpfgprog
