// image: 640x480
camera { location <0, 0, -5> right x*image_width/image_height look_at <0,0,0> }
// model: camera = { location: <0, 0, -5>, direction: <0, 0, 1>, right: <1.3333333333333333, 0, 0>, up: <0, 1, 0> }
