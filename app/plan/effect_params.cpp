#include "plan/effect_params.hpp"

#include "plan/number_text.hpp"


namespace plan {

ResolvedEffects resolve_effects(const EffectParams& params, scene::Scene& scene,
                                const frustum::MatrixPair<float>* camera) {
    ResolvedEffects resolved{params, place_mirror(scene, params.mirror_place, camera), std::nullopt};
    EffectParams& p = resolved.params;
    if (scene.mirror) {
        const float limit_m = max_sagitta_m(*scene.mirror, p.curved.shape);
        if (!p.sagitta_given) {
            p.curved.sagitta_m = fit_sagitta_m(*scene.mirror, p.curved.shape, scene.world_bounds);
        } else if (!(p.curved.sagitta_m <= limit_m)) {
            resolved.refused = "--sagitta " + number_text(p.curved.sagitta_m) + " must be in [0, " +
                               number_text(limit_m) + "] m for this mirror (half the distance from its centre to its rim)";
        }
    }
    return resolved;
}

std::optional<StereoRig> stereo_rig(const EffectParams& params, const frustum::MatrixPair<float>& camera,
                                    const scene::Scene& scene) {
    if (!params.stereo) {
        return std::nullopt;
    }
    StereoRig rig;
    rig.ipd_m = params.ipd_m;
    rig.convergence_m = params.convergence_m ? *params.convergence_m
                                             : default_convergence_m(camera, scene.mirror, scene.world_bounds);
    return rig;
}

} // namespace plan
