uniform float Wide < float UIMin = 0; float UIMax = 1e30; > = 1;
plugin Q < string Type = "film-fit"; string Target = "TargetColour"; string Vary = "Wide"; string OuterIndex = "OuterIndex"; string FilmIndex = "FilmIndex"; string SubstrateIndex = "SubstrateIndex"; >;
