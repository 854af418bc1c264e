fog { fog_type 3 distance 10 }
// error: 1:7 fog_type must be 1 or 2, found 3
// hint: 1 is constant fog, 2 ground fog
