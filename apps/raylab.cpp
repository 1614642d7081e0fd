// raylab command-line entry point (sub-commands are added as they land).
#include <cstdio>

int main() {
    std::fprintf(stderr, "usage: raylab render SCENE -o OUT.exr [options]\n");
    return 2;
}
