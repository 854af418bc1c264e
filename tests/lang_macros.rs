//! Macros that change their caller's identifiers (POV-Ray passes bare identifiers by
//! reference), including when the assignment is the last thing in the body and has no `;`.

use glam::DVec3;
use penumbra::lang::{LoadOptions, load_scene_source};

#[test]
fn a_macro_can_replace_an_object_passed_by_reference() {
    let source = "#version 3.7;
#macro Turn_Me(Stuff, Degrees, Axis)
    #declare Stuff = object { Stuff rotate Axis*Degrees }
#end
#macro Shift(Stuff) #declare Stuff = object { Stuff translate 2*x }; #end
#declare Thing = sphere { <0, 1, 0>, 0.5 }
Turn_Me(Thing, -90, x)
Shift(Thing)
object { Thing }
";
    let scene = load_scene_source("macros.pov", source, &LoadOptions::default())
        .expect("loads")
        .scene;
    assert_eq!(scene.objects.len(), 1);
    // rotate x*-90 takes <0,1,0> to <0,0,-1>; then the shift along x.
    let centre = scene.objects[0].transform.point(DVec3::new(0.0, 1.0, 0.0));
    assert!(
        (centre - DVec3::new(2.0, 0.0, -1.0)).length() < 1e-12,
        "the macros did not change Thing: {centre}"
    );
}
