#version 330 core
// Paper: two-sided, a key light from above, a second key over the viewer's shoulder, a
// little of the key shining through, plus sky/ground ambient. A share of the facet
// normal (from screen-space derivatives) is mixed in so that creases read as
// creases even where the Hermite-smoothed normals round them off.
in vec3 vPos;
in vec3 vNormal;
in vec4 vColor;
in vec2 vUv;
uniform vec3 uEye;
uniform vec3 uBaseColor;
uniform float uAlpha;
uniform sampler2D uTexture;
uniform float uTextured; // 1: the colour is multiplied by the paper's texture
uniform float uFacet;
out vec4 fragColor;
void main() {
    vec3 view = normalize(uEye - vPos);
    vec3 n = normalize(vNormal);
    if (dot(n, view) < 0.0) n = -n;
    vec3 facet = normalize(cross(dFdx(vPos), dFdy(vPos)));
    if (dot(facet, view) < 0.0) facet = -facet;
    n = normalize(mix(n, facet, uFacet));

    vec3 key = normalize(vec3(0.35, 1.0, 0.45));
    vec3 fill = normalize(vec3(-0.6, 0.4, -0.5));
    // A second key over the viewer's shoulder, as a photographer's: paper turned to the
    // view is lit wherever it faces, so a hanging sheet reads as paper, not desk grey.
    vec3 shoulder = normalize(view + vec3(0.0, 0.25, 0.0));
    float diffuse = max(dot(n, key), 0.0);
    float fillLight = max(dot(n, fill), 0.0);
    float shoulderLight = max(dot(n, shoulder), 0.0);
    // Paper is thin: a little of the key shines through to the side turned from it.
    float through = max(-dot(n, key), 0.0);
    float hemi = 0.5 + 0.5 * n.y;
    vec3 ambient = mix(vec3(0.50, 0.48, 0.46), vec3(0.62, 0.64, 0.68), hemi);
    vec3 halfway = normalize(key + view);
    float spec = pow(max(dot(n, halfway), 0.0), 24.0) * 0.06;

    vec3 paper = uBaseColor;
    if (uTextured > 0.5) paper *= texture(uTexture, vUv).rgb;
    vec3 base = mix(paper, vColor.rgb, vColor.a);
    vec3 color = base * (0.36 * ambient + 0.34 * diffuse + 0.05 * fillLight +
                         0.55 * shoulderLight + 0.10 * through) + vec3(spec);
    fragColor = vec4(color, uAlpha);
}
