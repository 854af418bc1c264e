#declare B = box { -1, 1 }
difference { object { B } sphere { 0, 1.2 } inverse no_image }
intersection { sphere { 0, 1 } sphere { x, 1 } clipped_by { plane { y, 0 } } translate y }
merge { sphere { 0, 1 } sphere { x, 1 } hollow no_reflection double_illuminate }
sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }
// model: objects[0].shape.Difference.0.len = 2
// model: objects[0].flags = { inverse: true, no_image: true }
// model: objects[1].clipping.Some.0.clipped_by.len = 1
// The later translate moves the clipping plane too.
// model: objects[1].clipping.Some.0.clipped_by[0].transform maps <0, 0, 0> to <0, 1, 0>
// model: objects[2].shape.Merge.0.len = 2
// model: objects[2].flags = { hollow: true, no_reflection: true, double_illuminate: true, no_shadow: false }
// model: objects[3].clipping.Some.0.clipped_by[0].shape.Box = { corner1: <-1, -1, -1>, corner2: <1, 1, 1> }
