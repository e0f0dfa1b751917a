!> The *DATABASE_SLEOUT file 'sleout': the energy of each contact interface at the request's
!> DT. Per output time a line 'time = t', one line per interface (deck order)
!>    interface=  <id>  slave=  Es  master=  Em  frictional=  0  total=  Es + Em
!> and a summary line with the sums over the interfaces and 'total energy ='. The energy of
!> a side is minus the work the contact forces did on its nodes since t = 0 (the centred
!> work of glstat's sliding interface energy, dx_energy_sums%interface_work): the penalty
!> energy stored in the interface plus what friction dissipated. So the summary's total is
!> glstat's sliding_interface energy to round-off. The frictional part is not split out
!> (written 0: it is inside slave and master). Contents after LS-DYNA's sleout (LS-DYNA
!> Keyword User's Manual Vol. I, *DATABASE_SLEOUT: "sliding interface energy", slave and
!> master side per interface); the exact column layout of LS-DYNA's file could not be
!> checked against a reference file, so readers should split at the labels. Numbers with
!> 10 significant digits. A deck without *CONTACT gets the time lines and zero totals.
module dx_sleout
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_IO
   use dx_model, only: model_t
   implicit none
   private
   public :: sleout_header, sleout_record

   character(*), parameter :: NUM = 'es18.10e3'

contains

   !> The header: title and the interfaces.
   function sleout_header(model) result(text)
      type(model_t), intent(in) :: model
      character(:), allocatable :: text
      character, parameter :: nl = new_line('a')
      character(:), allocatable :: title
      character(120) :: line
      integer :: i
      title = ''
      if (allocated(model%title)) title = trim(model%title)
      text = ' contact interface energy file, sleout: '//title//nl// &
             ' dynx sleout (energy = -work of the contact forces; 10 significant digits)'//nl
      if (allocated(model%contact)) then
         do i = 1, size(model%contact%iface)
            write(line, '(" interface ",i10,"   ",a)') model%contact%iface(i)%label, &
               model%contact%iface(i)%name
            text = text//trim(line)//nl
         end do
      end if
   end function sleout_header

   !> One output time: each interface's energies and the summary.
   subroutine sleout_record(model, text, error)
      type(model_t), intent(in) :: model
      character(:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: error
      character, parameter :: nl = new_line('a')
      character(240) :: line
      character(256) :: msg
      real(wp) :: es, em, ts, tm
      integer :: i, ios
      ios = 0
      ts = 0.0_wp; tm = 0.0_wp
      fmt: block
         write(line, '(" time = ",'//NUM//')', iostat=ios, iomsg=msg) model%time
         if (ios /= 0) exit fmt
         text = nl//trim(line)//nl
         if (allocated(model%contact)) then
            do i = 1, size(model%contact%iface)
               ! at t(n): the work without the v(n+1/2) half of this cycle's (as glstat)
               es = -(model%contact%iface(i)%wslave - model%contact%iface(i)%hslave) + 0.0_wp
               em = -(model%contact%iface(i)%wmaster - model%contact%iface(i)%hmaster) + 0.0_wp
               ts = ts + es; tm = tm + em
               write(line, '(" interface=",i10,"   slave= ",'//NUM//',"   master= ",'//NUM// &
                     ',"   frictional= ",'//NUM//',"   total= ",'//NUM//')', iostat=ios, &
                     iomsg=msg) model%contact%iface(i)%label, es, em, 0.0_wp, es + em
               if (ios /= 0) exit fmt
               text = text//trim(line)//nl
            end do
         end if
         write(line, '(" summary             slave= ",'//NUM//',"   master= ",'//NUM// &
               ',"   frictional= ",'//NUM//',"   total energy= ",'//NUM//')', iostat=ios, &
               iomsg=msg) ts, tm, 0.0_wp, ts + tm
         if (ios /= 0) exit fmt
         text = text//trim(line)//nl
      end block fmt
      if (ios /= 0) call set_error(error, 'cannot format a sleout record: '//trim(msg), &
                                   EXIT_IO)
   end subroutine sleout_record
end module dx_sleout
