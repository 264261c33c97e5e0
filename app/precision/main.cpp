// frustum-depth-precision [--scene FILE.gltf] [--data FILE]: the tables of
// docs/depth-precision.md (metres per depth step, with and without the
// oblique near plane), and with --data the plot's columns for gnuplot.
#include "precision/depth_precision.hpp"

#include <scene/load_gltf.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

const char* range_name(frustum::DepthRange range) {
    switch (range) {
    case frustum::DepthRange::MinusOneToOne: return "[-1,1]";
    case frustum::DepthRange::ZeroToOne: return "[0,1]";
    case frustum::DepthRange::ReversedZeroToOne: return "reversed";
    }
    return "?";
}

std::string mm(const std::optional<double>& metres) {
    if (!metres) {
        return "clipped";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", *metres * 1000.0);
    return text;
}

std::string ratio(const precision::Sample& s) {
    if (!s.oblique_m || !s.plain_m) {
        return "-";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", *s.oblique_m / *s.plain_m);
    return text;
}

std::string header(const char* first) {
    std::string line = std::string("| ") + first + " |", rule = "|---|";
    for (auto range : precision::kRanges) {
        for (auto storage : precision::kStorages) {
            line += std::string(" ") + range_name(range) + " " +
                    (storage == precision::Storage::Fixed24 ? "fixed24" : "float32") + " |";
            rule += "---|";
        }
    }
    return line + "\n" + rule + "\n";
}

// Rows of 6 cells (ranges x storages, as kRanges x kStorages), each
// "oblique (plain, xratio)" in mm per step.
std::string table(const std::vector<precision::Sample>& samples, const char* first, bool by_tilt) {
    std::string text = header(first);
    for (std::size_t i = 0; i + 6 <= samples.size(); i += 6) {
        std::ostringstream key;
        key << (by_tilt ? samples[i].tilt_deg : samples[i].distance_m);
        text += "| " + key.str() + " |";
        for (std::size_t k = i; k < i + 6; ++k) {
            text += " " + mm(samples[k].oblique_m) + " (" + mm(samples[k].plain_m) + ", x" + ratio(samples[k]) + ") |";
        }
        text += "\n";
    }
    return text;
}

} // namespace

int main(int argc, char** argv) {
    std::string scene_path = "assets/showcase.gltf", data_path;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if ((arg == "--scene" || arg == "--data") && i + 1 < argc) {
            (arg == "--scene" ? scene_path : data_path) = argv[++i];
        } else {
            std::cerr << "frustum-depth-precision: unknown argument '" << arg
                      << "' (expected --scene FILE.gltf or --data FILE)\n";
            return 2;
        }
    }
    auto scene = scene::load_gltf(scene_path);
    if (!scene) {
        std::cerr << "frustum-depth-precision: " << scene.error() << "\n";
        return 1;
    }
    auto showcase = precision::showcase_samples(*scene, {0.25, 0.5, 1.0, 2.0, 4.0});
    if (!showcase) {
        std::cerr << "frustum-depth-precision: " << showcase.error() << "\n";
        return 1;
    }
    const std::vector<double> tilts{0, 10, 20, 30, 40, 50, 60, 70, 80};
    const std::vector<double> distances{2.5, 10.0, 50.0};
    const auto planes = precision::random_plane_samples(tilts, distances, 64);

    std::ostringstream out;
    out << "Showcase mirror (plane " << (*showcase)[0].tilt_deg
        << " degrees from the reflected near plane); mm per depth step, oblique (un-clipped, x ratio), by "
           "distance from the reflected eye in m:\n\n"
        << table(*showcase, "distance m", false) << "\n";
    for (double distance : distances) {
        std::vector<precision::Sample> at;
        for (const auto& s : planes) {
            if (s.distance_m == distance) {
                at.push_back(s);
            }
        }
        out << "Random planes (" << at[0].planes << " per tilt, medians), " << distance
            << " m down the axis; mm per depth step, oblique (un-clipped, x ratio), by tilt in degrees:\n\n"
            << table(at, "tilt deg", true) << "\n";
    }
    if (!data_path.empty()) {
        std::ostringstream data;
        data << "# random planes: tilt_deg distance_m, then per range ([-1,1], [0,1], reversed) x storage "
                "(fixed24, float32): oblique mm, plain mm per step (-1: clipped)\n";
        for (double distance : distances) { // one gnuplot data block (index) per distance
            data << (distance == distances.front() ? "" : "\n\n");
            for (std::size_t i = 0; i < planes.size(); i += 6) {
                if (planes[i].distance_m != distance) {
                    continue;
                }
                data << planes[i].tilt_deg << " " << planes[i].distance_m;
                for (std::size_t k = i; k < i + 6; ++k) {
                    data << " " << (planes[k].oblique_m ? *planes[k].oblique_m * 1000.0 : -1.0) << " "
                         << (planes[k].plain_m ? *planes[k].plain_m * 1000.0 : -1.0);
                }
                data << "\n";
            }
        }
        std::ofstream file(data_path);
        file << data.str();
        if (!file) {
            std::cerr << "frustum-depth-precision: cannot write --data '" << data_path << "'\n";
            return 1;
        }
    }
    std::cout << out.str();
    return 0;
}
