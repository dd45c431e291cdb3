// placeholder until the polygonizer tests land
