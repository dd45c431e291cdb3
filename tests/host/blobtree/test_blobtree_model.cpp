// placeholder until the model tests land
