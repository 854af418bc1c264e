sphere { 0, 1 hollow no_image no_reflection double_illuminate inverse rotate y*90 scale <1,2,3> }
// model: objects[0].flags = { hollow: true, no_image: true, no_reflection: true, double_illuminate: true, inverse: true }
// rotate y*90 takes +x to -z, then the scale stretches z by 3.
// model: objects[0].transform maps <1, 0, 0> to <0, 0, -3>
