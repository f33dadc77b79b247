// Every std430 block the host fills or reads is laid out in C++ exactly as GLSL lays it out: each
// field's offset and each array's stride, queried from the linked production programs
// (program interface queries, OpenGL 4.5 core §7.3.1). A field counts as checked only where a
// program uses it (unused fields are not active), so every listed field must be active in some
// program; the fields no shader reads (pads, host-only fields) are covered by the array stride.
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/camera_geometry.h"
#include "gpu/program.h"
#include "shaders/shared/gbuffer_kernel.h"
#include "shaders/shared/lighting.h"
#include "shaders/shared/lpv/lpv_types.h"
#include "shaders/shared/svo/build_kernel.h"
#include "shaders/shared/compose.h"
#include "shaders/shared/cone/cone_types.h"
#include "shaders/shared/vct/diffuse_upsample.h"
#include "shaders/shared/cone/voxel_light.h"
#include "shaders/shared/texture_layout.h"
#include "shaders/shared/voxelize_layout.h"
#include "tests/gl_contexts.h"

namespace voxgi::test {
namespace {

using namespace shared;

// Every program the GPU stages link, named after its shaders (docs/architecture.md, "Shaders"): a
// compute shader is a program of its own; the vertex, geometry and fragment shaders of one stem
// ("lpv/rsm.vert", "lpv/rsm.frag") are one program, "lpv/rsm".
std::map<std::string, std::vector<const ShaderSource*>> stagePrograms() {
  std::map<std::string, std::vector<const ShaderSource*>> programs;
  for (const ShaderSource* s : shaders::kAll) {
    const std::string name(s->name);
    programs[name.substr(0, name.rfind('.'))].push_back(s);
  }
  return programs;
}

struct Field {
  const char* name;
  size_t offset;  // offsetof in the C++ struct
};
#define VOXGI_FIELD(type, member)   \
  Field {                           \
#member, offsetof(type, member) \
  }

// A struct as a block member: `variable` is its GLSL name ("params", or "lights[0]" for an array
// whose first element starts at `base` bytes into the block and strides sizeof(type)).
struct Use {
  std::string program;  // a key of stagePrograms()
  std::string variable;
  size_t base;
  bool array;
};

struct Layout {
  const char* type;
  size_t size;
  std::vector<Field> fields;
  std::vector<Use> uses;
};

// The records shared by the stages of several techniques (shaders/shared/).
std::vector<Layout> commonLayouts() {
  return {
      {"VoxelTriangle",
       sizeof(VoxelTriangle),
       {VOXGI_FIELD(VoxelTriangle, v0), VOXGI_FIELD(VoxelTriangle, v1),
        VOXGI_FIELD(VoxelTriangle, v2), VOXGI_FIELD(VoxelTriangle, albedo),
        VOXGI_FIELD(VoxelTriangle, areaScale), VOXGI_FIELD(VoxelTriangle, normal),
        VOXGI_FIELD(VoxelTriangle, sampleArea), VOXGI_FIELD(VoxelTriangle, emission),
        VOXGI_FIELD(VoxelTriangle, uvFootprint), VOXGI_FIELD(VoxelTriangle, dominantAxis),
        VOXGI_FIELD(VoxelTriangle, subdivision), VOXGI_FIELD(VoxelTriangle, albedoTexture),
        VOXGI_FIELD(VoxelTriangle, emissionTexture), VOXGI_FIELD(VoxelTriangle, uv0),
        VOXGI_FIELD(VoxelTriangle, uv1), VOXGI_FIELD(VoxelTriangle, uv2)},
       {{"voxelize_antialiased", "triangles[0]", 0, true},
        {"voxelize", "triangles[0]", 0, true},
        {"voxelize_resolve", "triangles[0]", 0, true}}},
      {"TextureRecord",
       sizeof(TextureRecord),
       {VOXGI_FIELD(TextureRecord, offset), VOXGI_FIELD(TextureRecord, width),
        VOXGI_FIELD(TextureRecord, height), VOXGI_FIELD(TextureRecord, levels),
        VOXGI_FIELD(TextureRecord, wrapS), VOXGI_FIELD(TextureRecord, wrapT)},
       {{"voxelize_antialiased", "textureRecords[0]", 0, true},
        {"voxelize", "textureRecords[0]", 0, true},
        {"gbuffer", "textureRecords[0]", 0, true},
        {"lpv/rsm", "textureRecords[0]", 0, true}}},
      {"SurfaceTriangle",
       sizeof(SurfaceTriangle),
       {VOXGI_FIELD(SurfaceTriangle, normal), VOXGI_FIELD(SurfaceTriangle, objectId),
        VOXGI_FIELD(SurfaceTriangle, material), VOXGI_FIELD(SurfaceTriangle, uv0),
        VOXGI_FIELD(SurfaceTriangle, uv1), VOXGI_FIELD(SurfaceTriangle, uv2),
        VOXGI_FIELD(SurfaceTriangle, uvPerVoxel)},
       {{"gbuffer", "triangles[0]", 0, true}, {"lpv/rsm", "triangles[0]", 0, true}}},
      {"SurfaceDisc",
       sizeof(SurfaceDisc),
       {VOXGI_FIELD(SurfaceDisc, center), VOXGI_FIELD(SurfaceDisc, radius),
        VOXGI_FIELD(SurfaceDisc, normal), VOXGI_FIELD(SurfaceDisc, albedo),
        VOXGI_FIELD(SurfaceDisc, objectId), VOXGI_FIELD(SurfaceDisc, material)},
       {{"gbuffer_disc", "discs[0]", 0, true}}},
      {"MaterialData",
       sizeof(MaterialData),
       {VOXGI_FIELD(MaterialData, albedo), VOXGI_FIELD(MaterialData, specular),
        VOXGI_FIELD(MaterialData, emission), VOXGI_FIELD(MaterialData, textures)},
       {{"gbuffer", "materials[0]", 0, true},
        {"gbuffer_disc", "materials[0]", 0, true},
        {"lpv/rsm", "materials[0]", 0, true}}},
      {"LightData",
       sizeof(LightData),
       {VOXGI_FIELD(LightData, position), VOXGI_FIELD(LightData, boundingRadius),
        VOXGI_FIELD(LightData, direction), VOXGI_FIELD(LightData, spotCosine),
        VOXGI_FIELD(LightData, intensity), VOXGI_FIELD(LightData, falloff),
        VOXGI_FIELD(LightData, polynomialFalloff), VOXGI_FIELD(LightData, kind),
        VOXGI_FIELD(LightData, castsShadows)},
       {{"vct/light_voxels", "lights[0]", sizeof(LightVoxelsParams), true},
        {"vct/trace_cones", "lights[0]", sizeof(ConeTraceParams), true},
        {"lpv/rsm", "lights[0]", 0, true},
        {"lpv/shade", "lights[0]", 0, true},
        {"svo/propagate_inject", "lights[0]", sizeof(LightVoxelsParams), true},
        {"svo/shade", "lights[0]", sizeof(ConeTraceParams), true}}},
  };
}

// The records voxel cone tracing's (the octree's cone and light stages use them too).
std::vector<Layout> vctLayouts() {
  return {
      {"LightVoxelsParams",
       sizeof(LightVoxelsParams),
       {VOXGI_FIELD(LightVoxelsParams, resolution), VOXGI_FIELD(LightVoxelsParams, lightCount),
        VOXGI_FIELD(LightVoxelsParams, normalWeighted), VOXGI_FIELD(LightVoxelsParams, voxelShadow),
        VOXGI_FIELD(LightVoxelsParams, voxelSize), VOXGI_FIELD(LightVoxelsParams, shadowKappa),
        VOXGI_FIELD(LightVoxelsParams, shadowOffset), VOXGI_FIELD(LightVoxelsParams, emissive)},
       {{"vct/light_voxels", "params", 0, false}, {"svo/propagate_inject", "params", 0, false}}},
      {"LightVoxelsUpdate",
       sizeof(LightVoxelsUpdate),
       {VOXGI_FIELD(LightVoxelsUpdate, changedLow), VOXGI_FIELD(LightVoxelsUpdate, partial),
        VOXGI_FIELD(LightVoxelsUpdate, changedHigh), VOXGI_FIELD(LightVoxelsUpdate, padding)},
       {{"vct/light_voxels", "update", 0, false}}},
      {"ConeTraceParams",
       sizeof(ConeTraceParams),
       {VOXGI_FIELD(ConeTraceParams, resolution),
        VOXGI_FIELD(ConeTraceParams, topLevel),
        VOXGI_FIELD(ConeTraceParams, directional),
        VOXGI_FIELD(ConeTraceParams, diffuseConeCount),
        VOXGI_FIELD(ConeTraceParams, lightCount),
        VOXGI_FIELD(ConeTraceParams, firstHitDiffuse),
        VOXGI_FIELD(ConeTraceParams, kahlShadow),
        VOXGI_FIELD(ConeTraceParams, lightAngleSpecular),
        VOXGI_FIELD(ConeTraceParams, ambientOcclusion),
        VOXGI_FIELD(ConeTraceParams, maxSteps),
        VOXGI_FIELD(ConeTraceParams, diffuseScale),
        VOXGI_FIELD(ConeTraceParams, coneStep),
        VOXGI_FIELD(ConeTraceParams, coneOffset),
        VOXGI_FIELD(ConeTraceParams, minStep),
        VOXGI_FIELD(ConeTraceParams, maxDistance),
        VOXGI_FIELD(ConeTraceParams, tanHalfShadowAperture),
        VOXGI_FIELD(ConeTraceParams, shadowStrength),
        VOXGI_FIELD(ConeTraceParams, ambientLambda),
        VOXGI_FIELD(ConeTraceParams, voxelSize),
        VOXGI_FIELD(ConeTraceParams, specularFalloff),
        VOXGI_FIELD(ConeTraceParams, specularGrace),
        VOXGI_FIELD(ConeTraceParams, coneClearance),
        VOXGI_FIELD(ConeTraceParams, background),
        VOXGI_FIELD(ConeTraceParams, camera)},
       {{"vct/trace_cones", "params", 0, false},
        {"vct/bounce", "params", 0, false},
        {"svo/propagate_gather", "params", 0, false},
        {"svo/shade", "params", 0, false}}},
      {"ConeData",
       sizeof(ConeData),
       {VOXGI_FIELD(ConeData, direction), VOXGI_FIELD(ConeData, tanHalfAperture),
        VOXGI_FIELD(ConeData, weight)},
       {{"vct/trace_cones", "cones[0]", 0, true},
        {"vct/bounce", "cones[0]", sizeof(ConeTraceParams), true},
        {"svo/propagate_gather", "cones[0]", sizeof(ConeTraceParams), true}}},
      {"ObjectData",
       sizeof(ObjectData),
       {VOXGI_FIELD(ObjectData, specularTanHalfAperture), VOXGI_FIELD(ObjectData, shininess)},
       {{"vct/trace_cones", "objects[0]", 0, true}, {"svo/shade", "objects[0]", 0, true}}},
      {"DiffuseSample",
       sizeof(DiffuseSample),
       {VOXGI_FIELD(DiffuseSample, position), VOXGI_FIELD(DiffuseSample, normal),
        VOXGI_FIELD(DiffuseSample, radiance), VOXGI_FIELD(DiffuseSample, sums)},
       {{"vct/trace_cones", "samples[0]", 0, true},
        {"vct/trace_cones_samples", "samples[0]", 0, true}}},
      {"PixelTerms",
       sizeof(PixelTerms),
       {VOXGI_FIELD(PixelTerms, directDiffuse), VOXGI_FIELD(PixelTerms, directSpecular),
        VOXGI_FIELD(PixelTerms, indirectDiffuse), VOXGI_FIELD(PixelTerms, indirectSpecular),
        VOXGI_FIELD(PixelTerms, ambientOcclusion)},
       {{"vct/trace_cones", "terms[0]", 0, true}}},
      {"ComposeInput",
       sizeof(ComposeInput),
       {VOXGI_FIELD(ComposeInput, albedo), VOXGI_FIELD(ComposeInput, specular),
        VOXGI_FIELD(ComposeInput, emission), VOXGI_FIELD(ComposeInput, directDiffuse),
        VOXGI_FIELD(ComposeInput, directSpecular), VOXGI_FIELD(ComposeInput, indirectDiffuse),
        VOXGI_FIELD(ComposeInput, indirectSpecular), VOXGI_FIELD(ComposeInput, ambientOcclusion)},
       {{"vct/compose", "inputs[0]", 0, true}}},
  };
}

// The records light propagation volumes' (shaders/shared/lpv/lpv_types.h).
std::vector<Layout> lpvLayouts() {
  return {
      {"Vpl",
       sizeof(Vpl),
       {VOXGI_FIELD(Vpl, position), VOXGI_FIELD(Vpl, normal), VOXGI_FIELD(Vpl, flux)},
       {{"lpv/inject", "vpls[0]", sizeof(InjectParams), true}}},
      {"InjectParams",
       sizeof(InjectParams),
       {VOXGI_FIELD(InjectParams, resolution), VOXGI_FIELD(InjectParams, coefficients),
        VOXGI_FIELD(InjectParams, vplCount), VOXGI_FIELD(InjectParams, shiftRsmVpls),
        VOXGI_FIELD(InjectParams, scale)},
       {{"lpv/inject", "params", 0, false}}},
      {"PropagationEntry",
       sizeof(PropagationEntry),
       {VOXGI_FIELD(PropagationEntry, offset),
        {"sampled[0]", offsetof(PropagationEntry, sampled)},
        {"reprojected[0]", offsetof(PropagationEntry, reprojected)},
        {"blocking[0]", offsetof(PropagationEntry, blocking)}},
       {{"lpv/propagate", "entries[0]", sizeof(PropagateParams), true}}},
      {"PropagateParams",
       sizeof(PropagateParams),
       {VOXGI_FIELD(PropagateParams, resolution), VOXGI_FIELD(PropagateParams, coefficients),
        VOXGI_FIELD(PropagateParams, entryCount), VOXGI_FIELD(PropagateParams, occlude),
        VOXGI_FIELD(PropagateParams, clampNegative), VOXGI_FIELD(PropagateParams, halfPrecision),
        VOXGI_FIELD(PropagateParams, storageScale),
        VOXGI_FIELD(PropagateParams, inverseStorageScale)},
       {{"lpv/propagate", "params", 0, false}}},
      {"ShadeParams",
       sizeof(ShadeParams),
       {VOXGI_FIELD(ShadeParams, resolution), VOXGI_FIELD(ShadeParams, coefficients),
        VOXGI_FIELD(ShadeParams, lightCount), VOXGI_FIELD(ShadeParams, inverseCellArea),
        VOXGI_FIELD(ShadeParams, offsetCells), VOXGI_FIELD(ShadeParams, camera)},
       {{"lpv/shade", "params", 0, false}}},
      {"RsmView",
       sizeof(RsmView),
       {VOXGI_FIELD(RsmView, origin), VOXGI_FIELD(RsmView, perspective),
        VOXGI_FIELD(RsmView, forward), VOXGI_FIELD(RsmView, extent), VOXGI_FIELD(RsmView, right),
        VOXGI_FIELD(RsmView, up), VOXGI_FIELD(RsmView, light)},
       {{"lpv/rsm", "views[0]", sizeof(RsmParams), true},
        {"lpv/inject", "views[0]", sizeof(RsmParams), true},
        {"lpv/shade", "views[0]", sizeof(RsmParams), true},
        {"lpv/inject_geometry_rsm", "views[0]", sizeof(RsmParams), true}}},
      {"RsmParams",
       sizeof(RsmParams),
       {VOXGI_FIELD(RsmParams, resolution), VOXGI_FIELD(RsmParams, viewCount),
        VOXGI_FIELD(RsmParams, lightCount), VOXGI_FIELD(RsmParams, voxelSize),
        VOXGI_FIELD(RsmParams, biasTexels)},
       {{"lpv/rsm", "params", 0, false},
        {"lpv/inject", "rsm", 0, false},
        {"lpv/shade", "rsm", 0, false},
        {"lpv/inject_geometry_rsm", "rsm", 0, false}}},
  };
}

// The records the sparse voxel octree's.
std::vector<Layout> svoLayouts() {
  return {
      {"SvoSample",
       sizeof(SvoSample),
       {VOXGI_FIELD(SvoSample, position), VOXGI_FIELD(SvoSample, edge),
        VOXGI_FIELD(SvoSample, albedo), VOXGI_FIELD(SvoSample, density),
        VOXGI_FIELD(SvoSample, normal), VOXGI_FIELD(SvoSample, emission)},
       {{"svo/build", "samples[0]", 0, true}}},
  };
}

std::vector<Layout> layouts() {
  std::vector<Layout> all;
  for (auto* owner : {commonLayouts, vctLayouts, lpvLayouts, svoLayouts})
    for (Layout& layout : owner()) all.push_back(std::move(layout));
  return all;
}

TEST(Layout, EveryProgramLinksOnBothPlatforms) {
  for (gpu::GlPlatform p : {gpu::GlPlatform::osmesa, gpu::GlPlatform::egl}) {
    gpu::GlContext& context = glContext(p);
    context.makeCurrent();
    for (const auto& [name, stages] : stagePrograms())
      EXPECT_NO_THROW(gpu::Program(context.gl(), stages)) << name;
  }
}

TEST(Layout, EveryHostSharedStd430BlockMatchesCpp) {
  gpu::GlContext& context = glContext(gpu::GlPlatform::egl);
  context.makeCurrent();
  const gpu::Gl& gl = context.gl();
  std::map<std::string, std::unique_ptr<gpu::Program>> programs;
  for (const auto& [name, stages] : stagePrograms())
    programs[name] = std::make_unique<gpu::Program>(gl, stages);
  // A buffer variable's property, or -1 where the program has no such active variable.
  auto query = [&](const std::string& program, const std::string& variable, GLenum property) {
    if (!programs.contains(program)) ADD_FAILURE() << "no program " << program;
    if (!programs.contains(program)) return GLint(-1);
    const GLuint id = programs[program]->id();
    const GLuint index = gl.GetProgramResourceIndex(id, GL_BUFFER_VARIABLE, variable.c_str());
    if (index == GL_INVALID_INDEX) return GLint(-1);
    GLint value = -1;
    gl.GetProgramResourceiv(id, GL_BUFFER_VARIABLE, index, 1, &property, 1, nullptr, &value);
    return value;
  };
  for (const Layout& layout : layouts()) {
    EXPECT_EQ(layout.size % 16, 0u) << layout.type << ": std430 rounds a struct of vec4s to 16";
    for (const Field& f : layout.fields) {
      bool active = false;
      for (const Use& use : layout.uses) {
        const std::string variable = use.variable + "." + f.name;
        const GLint offset = query(use.program, variable, GL_OFFSET);
        if (offset < 0) continue;
        active = true;
        EXPECT_EQ(size_t(offset), use.base + f.offset) << layout.type << " " << variable;
        if (use.array) {
          EXPECT_EQ(size_t(query(use.program, variable, GL_TOP_LEVEL_ARRAY_STRIDE)), layout.size)
              << layout.type << " " << variable;
        }
      }
      EXPECT_TRUE(active) << layout.type << "." << f.name << " is active in no program";
    }
  }
}

}  // namespace
}  // namespace voxgi::test
