// tiling 13 to 24, 25 and 27 (Penrose's pentagons and rhombs, at the front): each on
// a square slab, with a colour map that gives every tile type its own colour and a light
// caulk at the bevelled edges (POV-Ray's type t owns the values t/N to (t+1)/N); every
// other slab also takes the pattern as its normal
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 11, -7>
  look_at <0, 0, -0.3>
  right x*image_width/image_height
  angle 48
}
light_source { <-3, 12, -6> color rgb 1 }

#macro Slab(N, Types, X, Z, Bumps)
  box { <-0.95, -0.1, -0.95>, <0.95, 0, 0.95>
    texture {
      pigment { tiling N
        color_map {
          #local T = 0;
          #while (T < Types)
            #local C = <mod(T, 2) * 0.6 + 0.2, mod(T, 3) * 0.3 + 0.1, 0.9 - T * 0.15>;
            [T / Types rgb C]
            [(T + 0.6) / Types rgb C * 0.7]
            [(T + 0.6) / Types rgb <0.95, 0.9, 0.8>]
            [(T + 1) / Types rgb <0.6, 0.55, 0.5>]
            #local T = T + 1;
          #end
        }
        scale 0.3 rotate y*15 translate <0.2, 0, 0.1> }
      #if (Bumps) normal { tiling N 0.4 scale 0.3 rotate y*15 translate <0.2, 0, 0.1> } #end
      finish { ambient 0.2 diffuse 0.7 specular 0.3 }
    }
    translate <X, 0, Z> }
#end

Slab(13, 3, -3, 3, false)
Slab(14, 5, -1, 3, true)
Slab(15, 2, 1, 3, false)
Slab(16, 3, 3, 3, true)
Slab(17, 6, -3, 1, false)
Slab(18, 2, -1, 1, true)
Slab(19, 3, 1, 1, false)
Slab(20, 3, 3, 1, true)
Slab(21, 6, -3, -1, false)
Slab(22, 3, -1, -1, true)
Slab(23, 3, 1, -1, false)
Slab(24, 5, 3, -1, true)
Slab(27, 2, -3, -3, false)
Slab(25, 6, -1, -3, true)
