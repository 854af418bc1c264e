//! The one table of POV-Ray's switches and INI keys: the parser, the "did you mean" hint and
//! docs/cli.md all read it.

/// What an option sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Setting {
    Input,
    Output,
    Width,
    Height,
    LibraryPath,
    Declare,
    Antialias,
    AntialiasThreshold,
    SamplingMethod,
    AntialiasDepth,
    Jitter,
    JitterAmount,
    Quality,
    WorkThreads,
    /// `+F[type][bits]`: output on or off, its type and bits per channel.
    OutputFile,
    OutputToFile,
    OutputFileType,
    BitsPerColour,
    StartRow,
    EndRow,
    StartColumn,
    EndColumn,
    Clock,
    InitialFrame,
    FinalFrame,
    InitialClock,
    FinalClock,
    SubsetStartFrame,
    SubsetEndFrame,
    CyclicAnimation,
    FrameStep,
    Display,
    Verbose,
    /// `+C`: resume from the checkpoint.
    ContinueTrace,
    PauseWhenDone,
    /// penumbra's own: write only the window (`--crop`).
    Crop,
    /// penumbra's own: `--frames A..B`.
    Frames,
    /// penumbra's own: `--spp N` (overrides the anti-aliasing mapping).
    Spp,
    /// penumbra's own: `--seed N`.
    Seed,
    /// penumbra's own: `--quiet`.
    Quiet,
    AllowWrite,
    /// penumbra's own: `--motion-blur N`.
    MotionBlur,
    /// penumbra's own: `--adaptive`, `--uniform`.
    Adaptive,
    Uniform,
    /// `-GD`: the scene's `#debug` text is not shown.
    DebugConsole,
    /// Accepted with a one-line note: does not apply to penumbra.
    NotApplicable,
}

/// One POV-Ray option: its switch (without the sign, upper case), its INI key, or
/// penumbra's own long option, what POV-Ray does with it and what penumbra does.
#[derive(Clone, Copy, Debug)]
pub struct PovOption {
    pub switch: Option<&'static str>,
    pub ini: Option<&'static str>,
    pub long: Option<&'static str>,
    pub setting: Setting,
    pub povray: &'static str,
    pub penumbra: &'static str,
}

const fn opt(
    switch: &'static str,
    ini: &'static str,
    setting: Setting,
    texts: [&'static str; 2],
) -> PovOption {
    PovOption {
        switch: if switch.is_empty() {
            None
        } else {
            Some(switch)
        },
        ini: if ini.is_empty() { None } else { Some(ini) },
        long: None,
        setting,
        povray: texts[0],
        penumbra: texts[1],
    }
}

const fn own(long: &'static str, setting: Setting, penumbra: &'static str) -> PovOption {
    PovOption {
        switch: None,
        ini: None,
        long: Some(long),
        setting,
        povray: "(penumbra's own)",
        penumbra,
    }
}

const IGNORED: &str = "accepted with a note; does not apply";

use Setting::*;

/// Every switch and INI key of POV-Ray 3.7, and penumbra's own additions.
pub const OPTIONS: &[PovOption] = &[
    opt(
        "I",
        "Input_File_Name",
        Input,
        ["scene file to render", "the same"],
    ),
    opt(
        "O",
        "Output_File_Name",
        Output,
        [
            "output file or folder (a name ending in / is a folder)",
            "the same; frames get the frame number before the extension",
        ],
    ),
    opt(
        "W",
        "Width",
        Width,
        ["image width in pixels", "the same (also `image_width`)"],
    ),
    opt(
        "H",
        "Height",
        Height,
        ["image height in pixels", "the same (also `image_height`)"],
    ),
    opt(
        "L",
        "Library_Path",
        LibraryPath,
        [
            "a folder searched for include files (repeatable)",
            "the same",
        ],
    ),
    opt(
        "",
        "Declare",
        Declare,
        [
            "`Declare=NAME=VALUE` defines a float before the scene is read",
            "the same",
        ],
    ),
    opt(
        "A",
        "Antialias",
        Antialias,
        [
            "adaptive anti-aliasing on (+A) or off (-A); `+An` also sets the threshold",
            "sets the samples per pixel (see the table below), sampled adaptively",
        ],
    ),
    opt(
        "",
        "Antialias_Threshold",
        AntialiasThreshold,
        [
            "colour difference that triggers supersampling (default 0.3)",
            "a lower threshold gives more samples (see the table below)",
        ],
    ),
    opt(
        "AM",
        "Sampling_Method",
        SamplingMethod,
        [
            "1: non-recursive, 2: recursive adaptive supersampling",
            "method 2 gives more samples (see the table below)",
        ],
    ),
    opt(
        "R",
        "Antialias_Depth",
        AntialiasDepth,
        [
            "supersampling depth (default 3)",
            "a deeper setting gives more samples (see the table below)",
        ],
    ),
    opt(
        "J",
        "Jitter",
        Jitter,
        [
            "jitter the supersamples (`+Jn` sets the amount)",
            "penumbra always jitters within strata; accepted",
        ],
    ),
    opt(
        "",
        "Jitter_Amount",
        JitterAmount,
        ["jitter amount (default 1)", "accepted"],
    ),
    opt(
        "AG",
        "Antialias_Gamma",
        NotApplicable,
        ["gamma for the anti-aliasing threshold test", IGNORED],
    ),
    opt(
        "AC",
        "Antialias_Confidence",
        NotApplicable,
        ["confidence for sampling method 3", IGNORED],
    ),
    opt(
        "Q",
        "Quality",
        Quality,
        [
            "0-1 quick colours, 2-3 no shadows, 4 no area lights, 5 area lights, 6-7 textures, 8 reflection and refraction, 9 media, 10-11 radiosity (default 9)",
            "the same cut-offs: below 4 no shadows, below 5 area lights as points, below 8 no reflection or refraction, below 9 no media, 0-1 pigment colour only",
        ],
    ),
    opt(
        "WT",
        "Work_Threads",
        WorkThreads,
        [
            "render threads",
            "the same (the image does not depend on it)",
        ],
    ),
    opt(
        "F",
        "",
        OutputFile,
        [
            "`+F` output on, `-F` off, `+Fx[n]` type x (N png, E exr, T tga, ...) with n bits",
            "N (png, 8 or 16 bits) and E (OpenEXR, linear); other types write png, with a note",
        ],
    ),
    opt(
        "",
        "Output_to_File",
        OutputToFile,
        ["write the image", "the same"],
    ),
    opt(
        "",
        "Output_File_Type",
        OutputFileType,
        ["N, E, T, C, P, S, B, H, J", "as `+F`"],
    ),
    opt(
        "",
        "Bits_Per_Color",
        BitsPerColour,
        ["bits per channel", "8 or 16 for png"],
    ),
    opt(
        "SR",
        "Start_Row",
        StartRow,
        [
            "first row rendered (pixel, from 1, or fraction 0.0-1.0)",
            "the same; the window's pixels equal the full render's",
        ],
    ),
    opt("ER", "End_Row", EndRow, ["last row rendered", "the same"]),
    opt(
        "SC",
        "Start_Column",
        StartColumn,
        ["first column rendered", "the same"],
    ),
    opt(
        "EC",
        "End_Column",
        EndColumn,
        ["last column rendered", "the same"],
    ),
    opt(
        "K",
        "Clock",
        Clock,
        ["the `clock` value of a still", "the same"],
    ),
    opt(
        "KFI",
        "Initial_Frame",
        InitialFrame,
        ["first frame number", "the same"],
    ),
    opt(
        "KFF",
        "Final_Frame",
        FinalFrame,
        [
            "last frame number: more than one frame makes an animation",
            "the same; frames named as POV-Ray names them",
        ],
    ),
    opt(
        "KI",
        "Initial_Clock",
        InitialClock,
        ["clock at the first frame (default 0)", "the same"],
    ),
    opt(
        "KF",
        "Final_Clock",
        FinalClock,
        ["clock at the last frame (default 1)", "the same"],
    ),
    opt(
        "SF",
        "Subset_Start_Frame",
        SubsetStartFrame,
        [
            "first frame of the subset rendered (number or fraction)",
            "the same",
        ],
    ),
    opt(
        "EF",
        "Subset_End_Frame",
        SubsetEndFrame,
        ["last frame of the subset", "the same"],
    ),
    opt(
        "KC",
        "Cyclic_Animation",
        CyclicAnimation,
        [
            "cyclic: the last frame stops one step short of the final clock",
            "the same",
        ],
    ),
    opt(
        "STP",
        "Frame_Step",
        FrameStep,
        ["render every n-th frame", "the same"],
    ),
    opt(
        "",
        "Clockless_Animation",
        NotApplicable,
        ["animation without clock", IGNORED],
    ),
    opt(
        "UF",
        "Field_Render",
        NotApplicable,
        ["interlaced field rendering", IGNORED],
    ),
    opt(
        "UO",
        "Odd_Field",
        NotApplicable,
        ["start with the odd field", IGNORED],
    ),
    opt(
        "D",
        "Display",
        Display,
        [
            "show the image while rendering (`+Dxy` sets the mode)",
            "penumbra has no display: `+D` is accepted with a note, `-D` is what it does",
        ],
    ),
    opt("", "Video_Mode", NotApplicable, ["display mode", IGNORED]),
    opt("", "Palette", NotApplicable, ["display palette", IGNORED]),
    opt(
        "",
        "Display_Gamma",
        NotApplicable,
        ["display gamma", IGNORED],
    ),
    opt(
        "SP",
        "Preview_Start_Size",
        NotApplicable,
        ["mosaic preview start size", IGNORED],
    ),
    opt(
        "EP",
        "Preview_End_Size",
        NotApplicable,
        ["mosaic preview end size", IGNORED],
    ),
    opt(
        "UD",
        "Draw_Vistas",
        NotApplicable,
        ["draw vista rectangles", IGNORED],
    ),
    opt(
        "P",
        "Pause_When_Done",
        PauseWhenDone,
        ["wait for a key when done", IGNORED],
    ),
    opt(
        "V",
        "Verbose",
        Verbose,
        [
            "verbose messages",
            "`-V` is like `--quiet` (no progress bar); `+V` is the default",
        ],
    ),
    opt(
        "X",
        "Test_Abort",
        NotApplicable,
        ["allow aborting with a key", IGNORED],
    ),
    opt(
        "",
        "Test_Abort_Count",
        NotApplicable,
        ["how often to test for abort", IGNORED],
    ),
    opt(
        "C",
        "Continue_Trace",
        ContinueTrace,
        [
            "resume an interrupted render",
            "continues from the checkpoint an interrupted render left beside its output (like `--resume`; docs/farm.md)",
        ],
    ),
    opt(
        "UA",
        "Output_Alpha",
        NotApplicable,
        ["write an alpha channel", IGNORED],
    ),
    opt(
        "B",
        "Buffer_Output",
        NotApplicable,
        ["output buffer (`+Bn` its size)", IGNORED],
    ),
    opt(
        "",
        "Buffer_Size",
        NotApplicable,
        ["output buffer size", IGNORED],
    ),
    opt(
        "",
        "File_Gamma",
        NotApplicable,
        [
            "gamma of the output file",
            "accepted with a note: png is always sRGB-encoded, exr linear",
        ],
    ),
    opt("", "Dither", NotApplicable, ["dither the output", IGNORED]),
    opt(
        "",
        "Dither_Method",
        NotApplicable,
        ["dither method", IGNORED],
    ),
    opt(
        "",
        "Grayscale_Output",
        NotApplicable,
        ["grey output", IGNORED],
    ),
    opt(
        "",
        "Histogram_Type",
        NotApplicable,
        ["render-time histogram", IGNORED],
    ),
    opt(
        "",
        "Histogram_Name",
        NotApplicable,
        ["histogram file", IGNORED],
    ),
    opt(
        "",
        "Histogram_Grid_Size",
        NotApplicable,
        ["histogram grid", IGNORED],
    ),
    opt(
        "BS",
        "Render_Block_Size",
        NotApplicable,
        ["block size per thread", IGNORED],
    ),
    opt(
        "",
        "Render_Block_Step",
        NotApplicable,
        ["block order step", IGNORED],
    ),
    opt(
        "RP",
        "Render_Pattern",
        NotApplicable,
        ["block order pattern", IGNORED],
    ),
    opt(
        "MI",
        "Max_Image_Buffer_Memory",
        NotApplicable,
        ["image buffer memory", IGNORED],
    ),
    opt(
        "HI",
        "Include_Header",
        NotApplicable,
        ["a file included before the scene", IGNORED],
    ),
    opt(
        "MV",
        "Version",
        NotApplicable,
        [
            "initial `#version`",
            "accepted with a note: the scene's own `#version` is used",
        ],
    ),
    opt(
        "MB",
        "Bounding",
        NotApplicable,
        ["automatic bounding (`+MBn` its threshold)", IGNORED],
    ),
    opt(
        "",
        "Bounding_Threshold",
        NotApplicable,
        ["bounding threshold", IGNORED],
    ),
    opt(
        "BM",
        "Bounding_Method",
        NotApplicable,
        ["bounding method", IGNORED],
    ),
    opt(
        "HR",
        "High_Reproducibility",
        NotApplicable,
        [
            "repeatable radiosity across threads (3.7)",
            "accepted with a note: every penumbra render is bit-identical for its seed",
        ],
    ),
    opt(
        "UL",
        "Light_Buffer",
        NotApplicable,
        ["light buffer", IGNORED],
    ),
    opt(
        "UV",
        "Vista_Buffer",
        NotApplicable,
        ["vista buffer", IGNORED],
    ),
    opt(
        "UR",
        "Remove_Bounds",
        NotApplicable,
        ["remove unneeded bounds", IGNORED],
    ),
    opt(
        "SU",
        "Split_Unions",
        NotApplicable,
        ["split unions for bounding", IGNORED],
    ),
    opt(
        "RF",
        "Radiosity_File_Name",
        NotApplicable,
        ["radiosity cache file", IGNORED],
    ),
    opt(
        "RFI",
        "Radiosity_From_File",
        NotApplicable,
        ["read the radiosity cache", IGNORED],
    ),
    opt(
        "RFO",
        "Radiosity_To_File",
        NotApplicable,
        ["write the radiosity cache", IGNORED],
    ),
    opt(
        "RVP",
        "Radiosity_Vain_Pretrace",
        NotApplicable,
        ["radiosity pretrace display", IGNORED],
    ),
    opt(
        "RTR",
        "Real_Time_Raytracing",
        NotApplicable,
        ["real-time animation loop", IGNORED],
    ),
    opt("", "Benchmark", NotApplicable, ["benchmark mode", IGNORED]),
    opt(
        "GA",
        "All_Console",
        NotApplicable,
        ["all text streams to the console", IGNORED],
    ),
    opt(
        "",
        "All_File",
        NotApplicable,
        ["all text streams to a file", IGNORED],
    ),
    opt(
        "GD",
        "Debug_Console",
        DebugConsole,
        [
            "the #debug stream (`+GDfile` to a file)",
            "the same on the console (`-GD` silences it); no file is written",
        ],
    ),
    opt(
        "",
        "Debug_File",
        NotApplicable,
        ["#debug stream file", IGNORED],
    ),
    opt(
        "GF",
        "Fatal_Console",
        NotApplicable,
        ["the fatal stream", IGNORED],
    ),
    opt(
        "",
        "Fatal_File",
        NotApplicable,
        ["fatal stream file", IGNORED],
    ),
    opt(
        "GR",
        "Render_Console",
        NotApplicable,
        ["the render stream", IGNORED],
    ),
    opt(
        "",
        "Render_File",
        NotApplicable,
        ["render stream file", IGNORED],
    ),
    opt(
        "GS",
        "Statistic_Console",
        NotApplicable,
        ["the statistics stream", IGNORED],
    ),
    opt(
        "",
        "Statistic_File",
        NotApplicable,
        ["statistics stream file", IGNORED],
    ),
    opt(
        "GW",
        "Warning_Console",
        NotApplicable,
        ["the warning stream", IGNORED],
    ),
    opt(
        "",
        "Warning_File",
        NotApplicable,
        ["warning stream file", IGNORED],
    ),
    opt(
        "GI",
        "Create_Ini",
        NotApplicable,
        ["write the options to an INI file", IGNORED],
    ),
    opt(
        "WL",
        "Warning_Level",
        NotApplicable,
        ["which warnings to show", IGNORED],
    ),
    opt(
        "",
        "Pre_Scene_Command",
        NotApplicable,
        ["shell command before the scene", IGNORED],
    ),
    opt(
        "",
        "Pre_Frame_Command",
        NotApplicable,
        ["shell command before each frame", IGNORED],
    ),
    opt(
        "",
        "Post_Frame_Command",
        NotApplicable,
        ["shell command after each frame", IGNORED],
    ),
    opt(
        "",
        "Post_Scene_Command",
        NotApplicable,
        ["shell command after the scene", IGNORED],
    ),
    opt(
        "",
        "User_Abort_Command",
        NotApplicable,
        ["shell command on abort", IGNORED],
    ),
    opt(
        "",
        "Fatal_Error_Command",
        NotApplicable,
        ["shell command on error", IGNORED],
    ),
    opt(
        "",
        "Pre_Scene_Return",
        NotApplicable,
        ["what its exit code does", IGNORED],
    ),
    opt(
        "",
        "Pre_Frame_Return",
        NotApplicable,
        ["what its exit code does", IGNORED],
    ),
    opt(
        "",
        "Post_Frame_Return",
        NotApplicable,
        ["what its exit code does", IGNORED],
    ),
    opt(
        "",
        "Post_Scene_Return",
        NotApplicable,
        ["what its exit code does", IGNORED],
    ),
    opt(
        "",
        "User_Abort_Return",
        NotApplicable,
        ["what its exit code does", IGNORED],
    ),
    opt(
        "",
        "Fatal_Error_Return",
        NotApplicable,
        ["what its exit code does", IGNORED],
    ),
    own(
        "crop",
        Crop,
        "write only the window of `+SR +ER +SC +EC` (POV-Ray writes the full size, the rest black)",
    ),
    own(
        "frames",
        Frames,
        "`--frames A..B`: frames A to B, like `+KFIA +KFFB`",
    ),
    own(
        "spp",
        Spp,
        "`--spp N`: samples per pixel, instead of what the anti-aliasing options give (a fractional N: an adaptive render's average)",
    ),
    own("seed", Seed, "`--seed N`: the sampler's seed"),
    own("quiet", Quiet, "no progress bar, no notes, no summary"),
    own(
        "allow-write",
        AllowWrite,
        "`--allow-write DIR`: the folder a scene's `#fopen ... write` may write into (nothing is written otherwise)",
    ),
    own(
        "motion-blur",
        MotionBlur,
        "`--motion-blur N`: each frame of an animation averages N times spread over its shutter (the frame's clock to the next frame's), parsed at each; POV-Ray 3.7 has no motion blur",
    ),
    own(
        "adaptive",
        Adaptive,
        "`--adaptive`: a pilot pass spreads the samples where the image changes (the default from 2 samples per pixel on, without motion blur)",
    ),
    own(
        "uniform",
        Uniform,
        "`--uniform`: every pixel takes the same samples",
    ),
];

/// The option named by a switch's text after its sign (`W640`, `KFI1`): the longest switch
/// that starts it, and the rest as its value.
pub fn find_switch(text: &str) -> Option<(&'static PovOption, &str)> {
    let upper = text.to_ascii_uppercase();
    OPTIONS
        .iter()
        .filter_map(|o| o.switch.map(|s| (o, s)))
        .filter(|(_, s)| upper.starts_with(s))
        .max_by_key(|(_, s)| s.len())
        .map(|(o, s)| (o, &text[s.len()..]))
}

pub fn find_ini(key: &str) -> Option<&'static PovOption> {
    OPTIONS
        .iter()
        .find(|o| o.ini.is_some_and(|k| k.eq_ignore_ascii_case(key)))
}

pub fn find_long(name: &str) -> Option<&'static PovOption> {
    OPTIONS.iter().find(|o| o.long == Some(name))
}

/// The known name nearest to `name` (edit distance, ignoring case), for "did you mean".
pub fn nearest<'a>(name: &str, known: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let name = name.to_ascii_uppercase();
    known
        .map(|k| (edit_distance(&name, &k.to_ascii_uppercase()), k))
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

/// The markdown table of every option, as docs/cli.md holds it.
pub fn markdown_table() -> String {
    let mut out =
        String::from("| switch | INI key | POV-Ray | penumbra |\n| --- | --- | --- | --- |\n");
    for o in OPTIONS {
        let switch = match (o.switch, o.long) {
            (Some(s), _) => format!("`+{s}`"),
            (None, Some(l)) => format!("`--{l}`"),
            (None, None) => String::new(),
        };
        let ini = o.ini.map(|k| format!("`{k}`")).unwrap_or_default();
        out.push_str(&format!(
            "| {switch} | {ini} | {} | {} |\n",
            o.povray, o.penumbra
        ));
    }
    out
}
