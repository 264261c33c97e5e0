// frustum-vectors: the only place that touches the process's streams.
#include "vectors/run.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
    return vectors::frustum_vectors_cli(args, std::cin, std::cout, std::cerr);
}
