#pragma once
#include <algorithm>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "scene/camera.hpp"

namespace tp::scene {

// The values each text setting of a scene may take: validateScene checks
// them, the viewer's panel offers them.
namespace choices {
inline const std::vector<std::string> kBoundary{"clamp", "wrap"};
inline const std::vector<std::string> kSphereForcing{"column", "spread"};
inline const std::vector<std::string> kRefraction{"accurate", "apparent"};
inline const std::vector<std::string> kAntialiasing{"off", "morphological"};
inline const std::vector<std::string> kAoPattern{"hammersley", "random"};
inline const std::vector<std::string> kAoDepthLookup{"interpolated", "nearest"};
inline const std::vector<std::string> kAoBlur{"off", "box", "bilateral"};
inline const std::vector<std::string> kAoResolution{"full", "half"};
inline const std::vector<std::string> kAoPreset{"fast", "balanced", "quality", "baseline"};
inline const std::vector<std::string> kNoise{"value", "value_cubic", "gradient", "simplex"};
inline const std::vector<std::string> kWallPattern{"plain", "brick", "tiles"};
inline const std::vector<std::string> kFloorPattern{"checker", "tiles"};
inline const std::vector<std::string> kGroundPattern{"checker", "terrace"};
inline const std::vector<std::string> kMaterial{"lambert", "glass"};
}  // namespace choices

// Clouds on a plane over the sky: a fractal sum of noise (shared/noise.h,
// normalised to [0, 1]) thresholded by the coverage, fading out towards the
// horizon. They hide the sky and its glow, never the sun (which lights the
// scene regardless).
struct Clouds {
  float coverage = 0.5f;  // 0: a clear sky, 1: overcast
  float scale = 0.6f;     // noise frequency on the cloud plane, per unit of its height
  unsigned octaves = 5;
  float persistence = 0.5f;
  unsigned seed = 3;
  std::string noise = "simplex";       // value | value_cubic | gradient | simplex
  glm::vec3 color{1.1f, 1.1f, 1.15f};  // radiance of a cloud
  bool operator==(const Clouds&) const = default;
};

// The procedural sky, in the terms a scene file uses. render/sky_model.cpp
// turns it into the shader's SkyParams.
struct Sky {
  float sunElevationDegrees = 35.0f;
  float sunAzimuthDegrees = 60.0f;  // from +x towards +z
  float sunAngularRadiusDegrees = 1.0f;
  glm::vec3 sunRadiance{5000.0f, 4700.0f, 4300.0f};
  glm::vec3 zenith{0.10f, 0.25f, 0.75f};
  glm::vec3 horizon{0.55f, 0.65f, 0.8f};
  glm::vec3 ground{0.25f, 0.23f, 0.2f};
  glm::vec3 glow{1.2f, 0.9f, 0.6f};
  float zenithExponent = 0.5f;   // shape of the horizon-to-zenith blend
  float glowExponent = 32.0f;    // tightness of the glow around the sun
  float horizonBlend = 0.02f;    // width of the sky-to-ground blend (sin of elevation)
  unsigned textureWidth = 2048;  // equirectangular texture; height is half
  // An equirectangular .exr or .hdr to use instead of the procedural sky
  // (absolute, or relative to the scene file); it lights the scene alone.
  std::string image;
  float rotationDegrees = 0.0f;  // of the image, about +y, from +x towards +z (as sun_azimuth)
  float intensity = 1.0f;        // the image's radiance scaled by this
  // Aerial perspective (shared/haze.h): metres of air over which a surface's
  // light gives way to the horizon's by 1 - 1/e; 0, clear air.
  float hazeDistance = 150.0f;
  Clouds clouds;
  bool operator==(const Sky&) const = default;
};

struct Ground {
  float halfExtent = 100.0f;
  float height = 0.0f;
  // checker: squares of albedoA and albedoB; terrace: pavers in running bond,
  // each its own tone between albedoA and albedoB, a coping of stones round
  // the pool, a lawn past the terrace (shared/surface_pattern.h).
  std::string pattern = "terrace";
  float checkerSize = 1.0f;
  glm::vec3 albedoA{0.42f, 0.37f, 0.30f};
  glm::vec3 albedoB{0.31f, 0.28f, 0.24f};
  float paverWidth = 0.6f;    // metres along x, joint included
  float paverDepth = 0.4f;    // metres along z, joint included
  float jointWidth = 0.012f;  // metres, between pavers and between coping stones
  glm::vec3 jointAlbedo{0.30f, 0.29f, 0.27f};
  float copingWidth = 0.3f;  // metres out from the pool's edge; 0: none
  glm::vec3 copingAlbedo{0.68f, 0.66f, 0.62f};
  float terraceHalfExtent = 6.0f;  // metres; past it the lawn; 0: the terrace runs to the edge
  glm::vec3 lawnAlbedo{0.14f, 0.22f, 0.07f};
  bool operator==(const Ground&) const = default;
};

// The pool that holds the water: a square hole in the ground, as wide as the
// water, with inner walls (plain, tiled, or running-bond brick with noise
// dirt) and a tiled or checkered floor shaped by value-noise terrain.
struct Pool {
  float depth = 1.2f;                         // mean floor depth below the rim (the ground)
  glm::vec3 wallAlbedo{0.55f, 0.56f, 0.58f};  // of plain walls
  std::string wallPattern = "tiles";          // plain | brick | tiles (as the floor)
  float brickWidth = 0.24f;                   // metres, joint included (courses repeat every brick width along)
  float brickHeight = 0.08f;                  // metres, joint included
  float mortarFraction = 0.15f;               // the joints' width as a fraction of the brick height
  glm::vec3 brickAlbedo{0.55f, 0.24f, 0.16f};
  glm::vec3 mortarAlbedo{0.62f, 0.60f, 0.55f};
  float dirt = 0.3f;                           // how much noise darkens the bricks (0: clean, 1: black at worst)
  std::string floorPattern = "tiles";          // checker (squares of tileAlbedoA and B) | tiles
  float tileSize = 0.2f;                       // metres, grout included
  glm::vec3 tileAlbedoA{0.34f, 0.64f, 0.72f};  // the tiles' tones run from A to B, one per tile
  glm::vec3 tileAlbedoB{0.20f, 0.50f, 0.64f};
  float groutWidth = 0.014f;  // metres
  glm::vec3 groutAlbedo{0.80f, 0.83f, 0.82f};
  float wallSpecular = 0.0f;  // the walls' glossy lobe's share (shared/glossy.h)
  float wallRoughness = 0.5f;
  bool operator==(const Pool&) const = default;
};

// The floor's terrain: octaves of bilinear value noise at frequency 2^i,
// amplitude persistence^i, normalised to [-amplitude/2, amplitude/2].
struct Terrain {
  float amplitude = 0.35f;  // metres, peak to peak
  float frequency = 0.8f;   // of the first octave, 1/m
  unsigned octaves = 4;
  float persistence = 0.5f;
  unsigned seed = 7;
  bool operator==(const Terrain&) const = default;
};

struct Keyframe {
  float time = 0.0f;  // seconds from the scene's start
  glm::vec3 center{0.0f};
  bool operator==(const Keyframe&) const = default;
};

// A sphere; with a path it moves (linearly between keyframes, held before the
// first and after the last) and pushes the water as it goes. Lambertian, or
// glass (docs/glass.md): refracting and reflecting the scene, seen directly
// and in the water.
struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 0.5f;
  glm::vec3 albedo{0.8f, 0.3f, 0.2f};  // of a lambert sphere
  float specular = 0.0f;               // the glossy lobe's share, 0 (Lambertian) to 1 (shared/glossy.h)
  float roughness = 0.5f;              // of the glossy lobe, 0 (sharpest) to 1 (a cosine lobe)
  std::vector<Keyframe> path = {};
  std::string material = "lambert";  // lambert | glass
  float ior = 1.5f;                  // of a glass sphere, in (1, 3]
  bool operator==(const Sphere&) const = default;
};

// Where the sphere's centre is at time t.
glm::vec3 sphereCenterAt(const Sphere& sphere, float t);

inline bool isGlass(const Sphere& sphere) { return sphere.material == "glass"; }

// A box, Lambertian or glass (docs/glass.md), turned about the vertical by
// `yaw`; it stands still. One that stands through the water's rest level
// is solid to the simulated water (sim::solidCellsOf); one wholly under it
// lets the water pass over it.
struct Box {
  glm::vec3 center{0.0f};
  glm::vec3 size{0.5f};                // edge lengths along its own x, y, z (metres)
  float yawDegrees = 0.0f;             // about +y, from +x towards -z
  glm::vec3 albedo{0.3f, 0.5f, 0.7f};  // of a lambert box
  std::string material = "lambert";    // lambert | glass
  float ior = 1.5f;                    // of a glass box, in (1, 3]
  bool operator==(const Box&) const = default;
};

inline bool isGlass(const Box& box) { return box.material == "glass"; }

// A raised-cosine drop into the water. Frame 0: part of the starting state
// (added to flat water, which then starts at rest). Frame k >= 1: added to the
// water as it stands after frame k-1, before the steps into frame k, so frame
// k is the first frame that shows it (render/water_timeline.hpp schedules it).
struct Drop {
  float x = 0.0f, z = 0.0f;  // world position of the centre
  float radius = 0.3f;
  float amplitude = 0.04f;
  unsigned frame = 0;
  bool operator==(const Drop&) const = default;
};

// The simulated water: a square of `extent` metres centred on the origin (the
// pool's size), at rest at height `level`, disturbed by drops at frame 0 and
// at later frames.
struct Water {
  bool enabled = true;
  unsigned grid = 128;
  float extent = 4.0f;
  float level = -0.15f;  // rest height of the surface (the rim is the ground's height)
  float waveSpeed = 0.6f;
  float damping = 0.3f;  // 1/s
  // 1/s: damps the shortest waves, which a moving sphere makes and which
  // barely travel (sim::WaterParams::gridDamping, docs/water-numerics.md).
  float gridDamping = 2.0f;
  std::string boundary = "clamp";
  // How a moving sphere displaces the water (sim::SphereForcing): "spread",
  // its submerged volume spread over the surface as the flow around the body
  // lifts it; "column", the volume in each column, whose edge at the
  // waterline steepens the wake as the grid is refined (docs/water-numerics.md).
  std::string sphereForcing = "spread";
  float maxSlope = 0.0f;
  float frameTime = 1.0f / 30.0f;  // seconds of simulation per rendered frame
  float ior = 1.333f;
  glm::vec3 absorption{0.45f, 0.09f, 0.06f};  // 1/m, red absorbed most
  // 1/m: light scattered once in the water (shared/water_scattering.h); 0: none, and no cost.
  glm::vec3 scattering{0.0f};
  float scatteringAnisotropy = 0.7f;  // Henyey-Greenstein g: forward scattering, as by particles
  // The shafts in the scattered sun light: the path cut into this many
  // pieces, each shadowed at its middle; 0: unshadowed (and cheaper).
  unsigned scatteringShadowPieces = 4;
  // Someone just jumped in: four drops about one point, of alternating sign,
  // sum to a trough ringed by crests and troughs; three small splashes round
  // it. By frame 60 the rings have spread into calm ripples.
  std::vector<Drop> drops{{-0.35f, 0.25f, 1.2f, 0.016f}, {-0.35f, 0.25f, 0.9f, -0.036f}, {-0.35f, 0.25f, 0.6f, 0.04f},
                          {-0.35f, 0.25f, 0.3f, -0.04f}, {0.45f, 0.95f, 0.09f, 0.012f},  {-1.25f, -0.35f, 0.08f, 0.01f},
                          {-0.1f, 1.45f, 0.08f, -0.01f}};
  bool operator==(const Water&) const = default;
};

struct Render {
  float exposure = 0.6f;
  // How the water shows what is under it: "accurate" casts each refracted ray
  // against the pool and spheres; "apparent" is the original's approximation,
  // reading the frame's own image of the pool at the refracted ray's mean-depth point.
  std::string refraction = "accurate";
  // The sun's light focused and spread by the waves on the pool floor (a
  // caustics pass); off, the floor is lit as through flat water, as the
  // reference (render --reference) lights it.
  bool caustics = true;
  // Binary-search steps for where a ray leaves a glass sphere (1 to 64).
  unsigned glassSearchSteps = 8;
  // A morphological filter of the tonemapped frame (the viewer's and the
  // PNG's; not the EXR's): "off" or "morphological". `render --samples N` is
  // the anti-aliasing of the linear frame.
  std::string antialiasing = "off";
  // The sun's shadows (shared/sun_shadow.h): from the opaque spheres, the
  // boxes and the pool's walls, soft by the sun's angular radius.
  bool shadows = true;
  bool operator==(const Render&) const = default;
};

// Screen-space ambient occlusion of the sky's light (render/ssao_model.cpp
// turns it into the shaders' parameters). The defaults are the balanced
// preset; aoPreset gives each preset.
struct Ao {
  bool enabled = true;
  std::string pattern = "hammersley";        // kernel and noise tile: hammersley | random (the LearnOpenGL baseline)
  unsigned kernelSize = 8;                   // hemisphere samples per pixel, 1..64
  float radius = 0.5f;                       // metres
  float bias = 0.025f;                       // metres: depth difference that does not count as occlusion
  unsigned noiseSize = 4;                    // side of the rotation tile in pixels, 1..8
  std::string depthLookup = "interpolated";  // depth at a sample: interpolated | nearest (the original's)
  std::string blur = "bilateral";            // off | box | bilateral
  unsigned blurTaps = 4;                     // per direction of the separable blur
  float blurDepthTolerance = 0.05f;  // bilateral blur and upsample: neighbours within this fraction of the view depth
  std::string resolution = "full";   // full | half (then a depth-aware upsample)
  bool operator==(const Ao&) const = default;
};

// The AO settings of a preset: fast | balanced | quality, chosen from the
// measured curve of run time against error (docs/ambient-occlusion.md), or
// baseline, the LearnOpenGL-style SSAO they are measured against. Throws
// std::invalid_argument naming the presets on any other name.
Ao aoPreset(const std::string& name);

struct Scene {
  Camera camera;
  Sky sky;
  Ground ground;
  Water water;
  Pool pool;
  Terrain terrain;
  // A red ball afloat.
  std::vector<Sphere> spheres{{.center = {0.9f, -0.2f, -0.7f}, .radius = 0.4f, .albedo = {0.75f, 0.12f, 0.06f}}};
  std::vector<Box> boxes;
  Render render;
  Ao ao;
  bool operator==(const Scene&) const = default;
};

// The built-in default scene, rendered when no --scene is given.
Scene defaultScene();

// The scene as it stands at time t (seconds from its start): every sphere
// where its path puts it.
Scene sceneAt(const Scene& scene, float t);

// The camera as it stands at frame `frame`, whose time is `frame` water
// frame times (cameraAt).
Camera cameraAtFrame(const Scene& scene, uint32_t frame);

// Whether any of the scene's spheres, any of its boxes, any of either is glass.
inline bool hasGlassSpheres(const Scene& scene) {
  return std::any_of(scene.spheres.begin(), scene.spheres.end(), [](const Sphere& s) { return isGlass(s); });
}
inline bool hasGlassBoxes(const Scene& scene) {
  return std::any_of(scene.boxes.begin(), scene.boxes.end(), [](const Box& b) { return isGlass(b); });
}
inline bool hasGlass(const Scene& scene) { return hasGlassSpheres(scene) || hasGlassBoxes(scene); }

// Throws with the field and the bound on the first impossible value.
void validateScene(const Scene& scene);
// The same for one of water.drops (a drop made live, too).
void validateDrop(const Drop& drop);

}  // namespace tp::scene
