// A component's own texture, moved by the transforms written after it, not before.
blob {
  sphere { 0, 1, 1 translate x pigment { rgb <1, 0, 0> } translate y }
  sphere { <1, 0, 0>, 1, 1 }
  pigment { rgb 1 }
}
// model: objects[0].shape.Blob.0.components[0].texture.Some.0.pigment.kind.Solid.0.rgb = <1, 0, 0>
// model: objects[0].shape.Blob.0.components[0].texture.Some.0.pigment.transform.forward.translation = <0, 1, 0>
// model: objects[0].shape.Blob.0.components[1].texture = None
