// frustum-vectors: the only place that touches the process's streams.
#include "vectors/run.hpp"

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

// No exception leaves main: an allocation failure is a one-line error, exit 1.
int main(int argc, char** argv) {
    try {
        std::ios::sync_with_stdio(false);
        const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
        return vectors::frustum_vectors_cli(args, std::cin, std::cout, std::cerr);
    } catch (const std::bad_alloc&) {
        std::cerr << "frustum-vectors: out of memory while reading or answering the request\n";
    } catch (const std::exception& error) {
        std::cerr << "frustum-vectors: internal error: " << error.what() << '\n';
    }
    return 1;
}
