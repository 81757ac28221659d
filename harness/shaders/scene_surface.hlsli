// Materials at a hit. The including entry declares StructuredBuffer<SceneMaterial>
// g_scene_materials (besides what scene_trace.hlsli needs).
#ifndef GLINT_SCENE_SURFACE_HLSLI
#define GLINT_SCENE_SURFACE_HLSLI

struct SceneSurface {
    float3 position;
    float3 normal; // unit, facing the incoming ray
    float3 baseColor;
    float metallic;
    float perceptualRoughness;
    float3 emissive;
    uint object;
};

SceneSurface SceneSurfaceAt(SceneHit hit, float3 origin, float3 dir)
{
    ScenePrimitive p = g_scene_primitives[hit.prim];
    SceneMaterial m = g_scene_materials[p.material];
    SceneSurface s;
    s.position = origin + dir * hit.t;
    s.normal = SceneHitNormal(hit, origin, dir);
    s.baseColor = m.baseColor;
    s.metallic = m.metallic;
    float ramp = saturate(dot(s.position, m.rampPlane.xyz) + m.rampPlane.w);
    s.perceptualRoughness = saturate(lerp(m.roughness, m.roughnessEnd, ramp));
    s.emissive = m.emissive;
    s.object = p.object;
    return s;
}

#endif // GLINT_SCENE_SURFACE_HLSLI
