; blind15 p01: a 4 cm cube among six close neighbours (2.5 cm gaps along
; x, 4.5 cm along y) goes to the tray; one tall shaker of the cluster goes
; to the rack. The other neighbours may be moved (to spare) but need not be.
(define (problem p01)
  (:domain counter-clutter)
  (:objects target pepper salt oil jar-l jar-r vinegar - item
            cluster tray rack spare - zone)
  (:init (at target cluster) (at pepper cluster) (at salt cluster)
         (at oil cluster) (at jar-l cluster) (at jar-r cluster)
         (at vinegar cluster) (handempty))
  (:goal (and (at target tray) (at pepper rack))))
