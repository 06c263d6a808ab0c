#include <sprout.hpp>
#include <cstdio>
int main() {
    auto r = sprout::parse("n: 2\nangle: 25.7\naxiom: F\nF -> F[+F]F[-F]F\n");
    if (!r.ok()) return 1;
    auto d = sprout::derive(r.grammar, r.grammar->settings.iterations);
    sprout::Geometry g;
    sprout::interpret(*d.string, *r.grammar, {}, g);
    std::printf("%s\n%zu segments\n", sprout::toString(*d.string, r.grammar->alphabet).c_str(), g.cylinders.size());
}
