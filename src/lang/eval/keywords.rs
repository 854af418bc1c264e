//! POV-Ray 3.7's reserved words. A word from this list that penumbra does not handle yet
//! is reported as "unsupported" rather than "unknown", so users can tell a typo from a
//! missing feature.

pub const KEYWORDS: &[&str] = &[
    "aa_level",
    "aa_threshold",
    "abs",
    "absorption",
    "accuracy",
    "acos",
    "acosh",
    "adaptive",
    "adc_bailout",
    "agate",
    "agate_turb",
    "albedo",
    "all",
    "all_intersections",
    "alpha",
    "altitude",
    "always_sample",
    "ambient",
    "ambient_light",
    "angle",
    "aoi",
    "aperture",
    "arc_angle",
    "area_illumination",
    "area_light",
    "array",
    "asc",
    "ascii",
    "asin",
    "asinh",
    "assumed_gamma",
    "atan",
    "atan2",
    "atanh",
    "atmosphere",
    "autostop",
    "average",
    "b_spline",
    "background",
    "bezier_spline",
    "bicubic_patch",
    "bitwise_and",
    "bitwise_or",
    "bitwise_xor",
    "black_hole",
    "blob",
    "blue",
    "blur_samples",
    "bokeh",
    "bounded_by",
    "box",
    "boxed",
    "bozo",
    "brick",
    "brick_size",
    "brightness",
    "brilliance",
    "bump_map",
    "bump_size",
    "bumps",
    "camera",
    "caustics",
    "ceil",
    "cells",
    "charset",
    "checker",
    "chr",
    "circular",
    "clipped_by",
    "clock",
    "clock_delta",
    "clock_on",
    "collect",
    "color",
    "color_map",
    "colour",
    "colour_map",
    "component",
    "composite",
    "concat",
    "cone",
    "confidence",
    "conic_sweep",
    "conserve_energy",
    "control0",
    "control1",
    "coords",
    "cos",
    "cosh",
    "count",
    "crackle",
    "crand",
    "cube",
    "cubic",
    "cubic_spline",
    "cubic_wave",
    "cutaway_textures",
    "cylinder",
    "cylindrical",
    "datetime",
    "declare",
    "defined",
    "degrees",
    "density",
    "density_file",
    "density_map",
    "dents",
    "deprecated",
    "df3",
    "difference",
    "diffuse",
    "dimension_size",
    "dimensions",
    "direction",
    "disc",
    "dispersion",
    "dispersion_samples",
    "dist_exp",
    "distance",
    "distance_maximum",
    "div",
    "double_illuminate",
    "eccentricity",
    "else",
    "emission",
    "end",
    "error_bound",
    "evaluate",
    "exp",
    "expand_thresholds",
    "exponent",
    "exr",
    "exterior",
    "extinction",
    "face_indices",
    "facets",
    "fade_color",
    "fade_colour",
    "fade_distance",
    "fade_power",
    "falloff",
    "falloff_angle",
    "false",
    "file_exists",
    "filter",
    "final_clock",
    "final_frame",
    "finish",
    "fisheye",
    "flatness",
    "flip",
    "floor",
    "focal_point",
    "fog",
    "fog_alt",
    "fog_offset",
    "fog_type",
    "for",
    "form",
    "frame_number",
    "frequency",
    "fresnel",
    "function",
    "gamma",
    "gather",
    "gif",
    "global_lights",
    "global_settings",
    "gradient",
    "granite",
    "gray",
    "gray_threshold",
    "green",
    "grey",
    "h_angle",
    "hdr",
    "height_field",
    "hexagon",
    "hf_gray_16",
    "hierarchy",
    "hollow",
    "hypercomplex",
    "if",
    "iff",
    "image_height",
    "image_map",
    "image_pattern",
    "image_width",
    "importance",
    "include",
    "initial_clock",
    "initial_frame",
    "input_file_name",
    "inside",
    "inside_vector",
    "int",
    "interior",
    "interior_texture",
    "internal",
    "interpolate",
    "intersection",
    "intervals",
    "inverse",
    "ior",
    "irid",
    "irid_wavelength",
    "isosurface",
    "jitter",
    "jpeg",
    "julia",
    "julia_fractal",
    "lambda",
    "lathe",
    "leopard",
    "light_group",
    "light_source",
    "linear_spline",
    "linear_sweep",
    "ln",
    "load_file",
    "local",
    "location",
    "log",
    "look_at",
    "looks_like",
    "low_error_factor",
    "macro",
    "magnet",
    "major_radius",
    "mandel",
    "map_type",
    "marble",
    "material",
    "material_map",
    "matrix",
    "max",
    "max_extent",
    "max_gradient",
    "max_intersections",
    "max_iteration",
    "max_sample",
    "max_trace",
    "max_trace_level",
    "maximum_reuse",
    "media",
    "media_attenuation",
    "media_interaction",
    "merge",
    "mesh",
    "mesh2",
    "mesh_camera",
    "metallic",
    "method",
    "metric",
    "min",
    "min_extent",
    "minimum_reuse",
    "mm_per_unit",
    "mod",
    "mortar",
    "natural_spline",
    "nearest_count",
    "no",
    "no_bump_scale",
    "no_image",
    "no_radiosity",
    "no_reflection",
    "no_shadow",
    "noise_generator",
    "normal",
    "normal_indices",
    "normal_map",
    "normal_vectors",
    "now",
    "number_of_waves",
    "object",
    "octaves",
    "off",
    "offset",
    "omega",
    "omnimax",
    "on",
    "once",
    "onion",
    "open",
    "optional",
    "orient",
    "orientation",
    "orthographic",
    "ovus",
    "panoramic",
    "parallel",
    "parametric",
    "pass_through",
    "pattern",
    "pavement",
    "perspective",
    "pgm",
    "phase",
    "phong",
    "phong_size",
    "photons",
    "pi",
    "pigment",
    "pigment_map",
    "pigment_pattern",
    "planar",
    "plane",
    "png",
    "point_at",
    "poly",
    "poly_wave",
    "polygon",
    "polynomial",
    "pot",
    "pow",
    "ppm",
    "precision",
    "precompute",
    "premultiplied",
    "pretrace_end",
    "pretrace_start",
    "prism",
    "prod",
    "projected_through",
    "pwr",
    "quadratic_spline",
    "quadric",
    "quartic",
    "quaternion",
    "quick_color",
    "quick_colour",
    "quilted",
    "radial",
    "radians",
    "radiosity",
    "radius",
    "rainbow",
    "ramp_wave",
    "rand",
    "range_divider",
    "ratio",
    "reciprocal",
    "recursion_limit",
    "red",
    "reflection",
    "reflection_exponent",
    "refraction",
    "repeat",
    "rgb",
    "rgbf",
    "rgbft",
    "rgbt",
    "right",
    "ripples",
    "rotate",
    "roughness",
    "samples",
    "save_file",
    "scale",
    "scallop_wave",
    "scattering",
    "seed",
    "select",
    "shadowless",
    "sin",
    "sine_wave",
    "sinh",
    "sint16be",
    "sint16le",
    "sint32be",
    "sint32le",
    "sint8",
    "size",
    "skipwhite",
    "sky",
    "sky_sphere",
    "slice",
    "slope",
    "slope_map",
    "smooth",
    "smooth_triangle",
    "solid",
    "sor",
    "spacing",
    "specular",
    "sphere",
    "sphere_sweep",
    "spherical",
    "spiral1",
    "spiral2",
    "spline",
    "split_union",
    "spotlight",
    "spotted",
    "sqr",
    "sqrt",
    "square",
    "srgb",
    "srgbf",
    "srgbft",
    "srgbt",
    "str",
    "strcmp",
    "strength",
    "strlen",
    "strlwr",
    "strupr",
    "sturm",
    "substr",
    "subsurface",
    "sum",
    "superellipsoid",
    "sys",
    "t",
    "tan",
    "tanh",
    "target",
    "tau",
    "text",
    "texture",
    "texture_list",
    "texture_map",
    "tga",
    "thickness",
    "threshold",
    "tiff",
    "tightness",
    "tile2",
    "tiles",
    "tiling",
    "tolerance",
    "toroidal",
    "torus",
    "trace",
    "transform",
    "translate",
    "transmit",
    "triangle",
    "triangle_wave",
    "triangular",
    "true",
    "ttf",
    "turb_depth",
    "turbulence",
    "type",
    "u",
    "u_steps",
    "uint16le",
    "uint8",
    "ultra_wide_angle",
    "union",
    "unit16be",
    "up",
    "use_alpha",
    "use_color",
    "use_colour",
    "use_index",
    "utf8",
    "uv_indices",
    "uv_mapping",
    "uv_vectors",
    "v",
    "v_angle",
    "v_steps",
    "val",
    "variance",
    "vaxis_rotate",
    "vcross",
    "vdot",
    "version",
    "vertex_vectors",
    "vlength",
    "vnormalize",
    "vrotate",
    "vstr",
    "vturbulence",
    "warp",
    "water_level",
    "waves",
    "while",
    "width",
    "wood",
    "wrinkles",
    "x",
    "y",
    "yes",
    "z",
];

pub fn is_keyword(name: &str) -> bool {
    KEYWORDS.binary_search(&name).is_ok()
}

/// Words that start a colour wherever an expression is expected.
pub fn is_colour_keyword(name: &str) -> bool {
    matches!(
        name,
        "color"
            | "colour"
            | "rgb"
            | "rgbf"
            | "rgbt"
            | "rgbft"
            | "srgb"
            | "srgbf"
            | "srgbt"
            | "srgbft"
            | "red"
            | "green"
            | "blue"
            | "filter"
            | "transmit"
    )
}

/// Built-in functions the evaluator implements.
pub fn is_function(name: &str) -> bool {
    matches!(
        name,
        "dimension_size"
            | "dimensions"
            | "sin"
            | "cos"
            | "tan"
            | "asin"
            | "acos"
            | "atan"
            | "sinh"
            | "cosh"
            | "tanh"
            | "asinh"
            | "acosh"
            | "atanh"
            | "atan2"
            | "sqrt"
            | "sqr"
            | "pow"
            | "exp"
            | "ln"
            | "log"
            | "abs"
            | "floor"
            | "ceil"
            | "int"
            | "mod"
            | "div"
            | "min"
            | "max"
            | "select"
            | "radians"
            | "degrees"
            | "bitwise_and"
            | "bitwise_or"
            | "bitwise_xor"
            | "vlength"
            | "vnormalize"
            | "vdot"
            | "vcross"
            | "vrotate"
            | "vaxis_rotate"
            | "str"
            | "vstr"
            | "concat"
            | "chr"
            | "asc"
            | "strlen"
            | "strupr"
            | "strlwr"
            | "substr"
            | "strcmp"
            | "val"
            | "file_exists"
            | "defined"
            | "seed"
            | "rand"
    )
}

/// Built-in functions POV-Ray has that need parts of the model penumbra lacks.
pub fn is_known_unsupported_function(name: &str) -> bool {
    matches!(
        name,
        "trace"
            | "inside"
            | "min_extent"
            | "max_extent"
            | "vturbulence"
            | "prod"
            | "sum"
            | "function"
            | "spline"
            | "datetime"
            | "now"
    )
}

/// Keywords that are values in expressions (constants and built-in identifiers).
pub fn is_expression_keyword(name: &str) -> bool {
    matches!(
        name,
        "pi" | "true"
            | "false"
            | "yes"
            | "no"
            | "on"
            | "off"
            | "x"
            | "y"
            | "z"
            | "t"
            | "u"
            | "v"
            | "image_width"
            | "image_height"
            | "clock"
            | "clock_delta"
            | "clock_on"
            | "initial_clock"
            | "final_clock"
            | "initial_frame"
            | "final_frame"
            | "frame_number"
            | "version"
    ) || is_function(name)
        || is_colour_keyword(name)
}
