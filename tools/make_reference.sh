#!/usr/bin/env bash
# Usage: make_reference.sh WAVETRACE SCENE OUT.exr SPP_PER_HALF WIDTH HEIGHT
# A converged reference made by our own renderer: two independent halves (seeds 1 and 2, so
# neither shares random numbers with a render at the scene's seed 0), each SPP_PER_HALF samples,
# with the accurate choice of every accuracy option (exact Fresnel, watertight triangles,
# cancellation-free spheres), so a fast option's bias shows up as error against it, and an
# unbiased caustic estimator: light tracing, never the photons (consistent, not unbiased, though
# the default where a scene has caustics), whose blur would then be part of the truth. The
# reference is the mean of the halves, stored as half-float EXR with zip compression. Its own
# noise is measured from the halves: the mean of two halves has a quarter of the variance of
# their difference, so its RMSE is RMSE(A, B) / 2 and its relMSE about relMSE(A, B) / 4.
set -euo pipefail
wavetrace=$1 scene=$2 out=$3 spp=$4 width=$5 height=$6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
reference_options=(--fresnel exact --triangle-test watertight --sphere-test cancellation_free --caustics light_tracing)
for seed in 1 2; do
  "$wavetrace" render "$scene" --width "$width" --height "$height" --spp "$spp" --seed "$seed" "${reference_options[@]}" \
    -o "$work/half$seed.exr"
done
oiiotool --nosoftwareattrib "$work/half1.exr" "$work/half2.exr" --add --mulc 0.5 -d half --compression zip -o "$work/reference.exr"
mv "$work/reference.exr" "$out"
echo "reference: $out ($((2 * spp)) spp, ${width}x${height}); the two halves against each other:"
halves=$("$wavetrace" compare "$work/half1.exr" "$work/half2.exr")
echo "$halves"
echo "$halves" | awk '$1 == "overall" { printf "reference noise: RMSE %.5g, relMSE %.4g (halves RMSE / 2, relMSE / 4)\n", $2 / 2, $3 / 4 }'
