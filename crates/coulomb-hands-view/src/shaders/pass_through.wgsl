// AR occlusion (thesis §3.6): whatever carries this material shows the background
// image's own pixel at each fragment, and writes its depth as usual. So a real hand
// (or real table) hides the virtual objects behind it and lets the camera image through,
// while objects in front of it are drawn over it: a depth-only mask over the background,
// whatever order the meshes are drawn in.

#import bevy_pbr::forward_io::VertexOutput
#import bevy_pbr::mesh_view_bindings::view

@group(#{MATERIAL_BIND_GROUP}) @binding(0) var background: texture_2d<f32>;
@group(#{MATERIAL_BIND_GROUP}) @binding(1) var background_sampler: sampler;

@fragment
fn fragment(in: VertexOutput) -> @location(0) vec4<f32> {
    // This view's own rectangle (one eye's half in stereo), stretched over the image.
    let uv = (in.position.xy - view.viewport.xy) / view.viewport.zw;
    return textureSample(background, background_sampler, uv);
}
